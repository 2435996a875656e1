#pragma once
// Two image sets compared image by image (`landsim compare`, docs/CROSSCHECK.md "Regression
// check"): the sets are folders written by `landsim render` (their manifest.json lists each
// image's view and frame); images are matched by view and frame index. Per image: the
// luminance's mean and regional relative differences, and the AOV layers' differences
// (depth, normal, object class, species). The regression check of a pipeline: render the
// scenario with a new landsim, compare with the stored set.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "exporters/noise_test.h"

namespace landsim::exporters {

struct ImageDifference {
  std::string view;
  int frame = 0;
  std::string path_a, path_b;  // relative to their sets
  bool size_mismatch = false;
  double luminance_mean_rel_diff = 0.0;        // |mean L_a - mean L_b| / mean L_b
  double luminance_region_max_rel_diff = 0.0;  // the same over the worst of 8 x 8 regions
  double depth_mean_rel_diff = 0.0;            // mean |d_a - d_b| / d_b where both see a surface
  double normal_mean_angle_deg = 0.0;          // mean angle between the normals where both have one
  double object_mismatch = 0.0;                // fraction of pixels whose object class differs
  double species_mismatch = 0.0;               // fraction of pixels whose species differs
  // Whether the luminance differs by more than the two renders' noise (both need their
  // variance layers).
  NoiseTest noise;
  bool pass = false;
};

struct CompareOptions {
  double max_mean_diff = 0.01;    // mean luminance, relative
  double max_region_diff = 0.05;  // worst region's luminance, relative
  double max_layer_diff = 0.01;   // depth (relative), object and species (fraction of pixels)
  double max_normal_deg = 1.0;    // mean normal angle
  // The noise test's significance level; with `statistical` it, not the relative
  // thresholds above, decides the luminance's verdict.
  double alpha = 0.001;
  bool statistical = false;
};

struct SetComparison {
  std::vector<ImageDifference> images;            // in set A's manifest order
  std::vector<std::string> only_in_a, only_in_b;  // "view f<frame>"
  bool pass = false;  // every image passes and both sets have the same images
};

// Throws InputError naming the folder or file when a set has no readable manifest.json or
// an image cannot be read.
SetComparison compare_image_sets(const std::filesystem::path& a, const std::filesystem::path& b,
                                 const CompareOptions& options);

// The comparison as one JSON object (`landsim compare --json`, docs/JSON.md).
std::string comparison_json(const SetComparison& c);

// report.json and report.html in `dir` (written atomically).
void write_compare_reports(const SetComparison& c, const CompareOptions& options,
                           const std::filesystem::path& a, const std::filesystem::path& b,
                           const std::filesystem::path& dir);

}  // namespace landsim::exporters
