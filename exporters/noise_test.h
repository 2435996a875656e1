#pragma once
// Whether two renders of one scene differ by more than their Monte Carlo noise
// (`landsim compare`, docs/SENSOR.md "Noise of the render"): each image carries the variance
// of every pixel's luminance estimate (the film's Y.variance), so a difference of means has a
// known standard error. Two z-scores are tested: the whole image's mean luminance, and the
// worst of the regions' means (Bonferroni-corrected for their number).
#include "renderer/output/film.h"

namespace landsim::exporters {

struct NoiseTest {
  bool available = false;     // both images carry a variance layer (rendered with 2+ spp)
  double image_z = 0.0;       // (mean_a - mean_b) / its standard error
  double region_max_z = 0.0;  // the largest |z| among the regions
  double image_threshold = 0.0, region_threshold = 0.0;  // |z| beyond these is a difference
  bool within_noise = true;
};

// Two-sided test at significance `alpha` over the image and `regions` x `regions` regions.
// The films have the same size.
NoiseTest noise_test(const renderer::Film& a, const renderer::Film& b, double alpha = 0.001,
                     int regions = 8);

// The region pixel (x, y) of a width x height image falls in when it is cut into `regions` x
// `regions` (row-major): the regions `landsim compare` reports the worst of.
inline int region_index(int x, int y, int width, int height, int regions) {
  return y * regions / height * regions + x * regions / width;
}

// The |z| a two-sided test at `alpha` rejects beyond: the standard normal's 1 - alpha / 2
// quantile.
double normal_quantile_two_sided(double alpha);

}  // namespace landsim::exporters
