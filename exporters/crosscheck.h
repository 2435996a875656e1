#pragma once
// Cross-check against POV-Ray: export the scene, render it with landsim in its
// POV-comparable mode and with POV-Ray (colour, and flat class colours for coverage), and
// compare: object coverage (intersection over union of the tree and ground masks) and
// relative luminance over the pixels both see as objects, overall and per region.
#include <array>
#include <filesystem>
#include <nlohmann/json_fwd.hpp>
#include <optional>
#include <string>

#include "renderer/scene.h"
#include "scenes/scenario/scenario.h"

namespace landsim::exporters {

struct CrosscheckOptions {
  std::filesystem::path out_dir;
  std::size_t view = 0;  // index into scene.views
  int spp = 16;          // landsim samples; POV-Ray gets the nearest n x n antialiasing grid
  int threads = 0;
  double min_iou = 0.98;
  double max_mean_diff = 0.05;
  double max_region_diff = 0.25;
  // Moves POV-Ray's camera (scene frame, metres): only to show that the check can fail.
  Vec3 pov_camera_shift;
  // A reference image of the user's instead of POV-Ray run on the spot (docs/CROSSCHECK.md
  // "Against a reference image"): any format the image module reads, float files taken as
  // cd/m2, integer files as an image at the export's exposure (pov_exposure_gain).
  std::filesystem::path reference;
  // Its class mask (LS_Mask's colours); without one, the reference's alpha (objects where
  // it is over 0.5) or no coverage at all.
  std::filesystem::path mask;
  // Before comparing, search translations of the reference of up to this many pixels (in
  // quarter pixels) for the one that fits landsim's render best.
  int align = 0;
  // A user's own POV-Ray scene, rendered by POV-Ray instead of the export, landsim rendering
  // the view at that scene's camera (docs/CROSSCHECK.md "Against a POV-Ray scene").
  std::filesystem::path pov_scene;
};

struct CrosscheckReport {
  double object_iou = 0.0;
  double tree_iou = 0.0, ground_iou = 0.0;
  std::optional<double> scene_object_iou;  // vehicles, structures ([[objects]]), when any
  double luminance_mean_rel_diff = 0.0;
  double luminance_region_max_rel_diff = 0.0;
  // Whether a class mask was compared (POV-Ray's, the --mask, or the reference's alpha);
  // when not, the IoUs stay 0 and do not count against passing.
  bool coverage_measured = true;
  std::optional<std::array<double, 2>> shift;  // the --align translation applied, pixels
  std::optional<renderer::View> camera;        // with pov_scene: the view read from its camera
  double landsim_seconds = 0.0;
  double povray_seconds = 0.0;
  bool pass = false;
};

// Writes in out_dir: pov/ (the export and POV-Ray's images), landsim.exr, side_by_side.png
// (landsim | POV-Ray | difference heat map), report.json and report.html. Throws
// std::runtime_error when POV-Ray cannot be run.
CrosscheckReport crosscheck(const scenes::Scenario& scenario, const renderer::Scene& scene,
                            const CrosscheckOptions& options);

// The report's `camera` (position, target in the scene frame, fov_y_deg), null without one.
nlohmann::json camera_json(const std::optional<renderer::View>& camera);

}  // namespace landsim::exporters
