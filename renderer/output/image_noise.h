#pragma once
// How noisy a rendered image is, from its own samples (docs/SENSOR.md "Noise of the render"):
// the per-pixel variance of the luminance estimate (the Y.variance layer) summed the way
// bench/image_error measures a render against a converged reference, so the manifest states
// the error a user would otherwise need a reference for (issue 72 item 3).
#include <optional>

#include "renderer/output/film.h"

namespace landsim::renderer {

struct ImageNoise {
  // The expected relative MSE of the luminance: the mean over pixels of variance /
  // (Y^2 + 0.01 mean(Y)^2), issue 46's measure with the pixel's own value for the reference's.
  double relative_mse = 0.0;
  // The standard error of the frame's mean luminance over that mean.
  double frame_relative_se = 0.0;
  // The median and 95th percentile over pixels of sqrt(variance) / sqrt(Y^2 + 0.01 mean^2).
  double pixel_relative_se_median = 0.0, pixel_relative_se_p95 = 0.0;
  double mean_spp = 0.0;
};

// Empty when the film cannot say: a pixel with fewer than 2 samples has no variance, or the
// frame is black.
std::optional<ImageNoise> image_noise(const Film& film);

}  // namespace landsim::renderer
