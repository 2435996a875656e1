#include "compare_command.h"

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include <iostream>

#include "crosscheck_command.h"
#include "exporters/image_set_compare.h"

namespace landsim::app {

CLI::App* add_compare_command(CLI::App& app, CompareArgs& args) {
  CLI::App* cmd =
      app.add_subcommand("compare",
                         "Compare two image sets written by landsim render, image by image (exit 3 "
                         "when they differ past the thresholds; docs/CROSSCHECK.md)");
  cmd->add_option("set_a", args.set_a, "The first image set (a folder with manifest.json)")
      ->required();
  cmd->add_option("set_b", args.set_b, "The second (the reference)")->required();
  cmd->add_option("--out", args.out, "Write report.json and report.html here");
  cmd->add_option("--max-mean-diff", args.max_mean_diff,
                  "Largest relative difference of an image's mean luminance")
      ->check(CLI::Range(0.0, 10.0))
      ->capture_default_str();
  cmd->add_option("--max-region-diff", args.max_region_diff,
                  "Largest relative difference of a region's (8 x 8) mean luminance")
      ->check(CLI::Range(0.0, 10.0))
      ->capture_default_str();
  cmd->add_option("--max-layer-diff", args.max_layer_diff,
                  "Largest mean relative depth difference, and fraction of pixels whose object "
                  "class or species differ")
      ->check(CLI::Range(0.0, 1.0))
      ->capture_default_str();
  cmd->add_option("--max-normal-deg", args.max_normal_deg, "Largest mean normal angle, degrees")
      ->check(CLI::Range(0.0, 180.0))
      ->capture_default_str();
  cmd->add_option("--alpha", args.alpha,
                  "Significance level of the noise test (both sets' variance layers)")
      ->check(CLI::Range(1e-12, 0.5))
      ->capture_default_str();
  cmd->add_flag("--statistical", args.statistical,
                "Judge luminance by the noise test (a difference beyond both renders' Monte "
                "Carlo noise) instead of --max-mean-diff and --max-region-diff");
  cmd->add_flag("--json", args.json, "Print the report as one JSON object on stdout");
  return cmd;
}

int run_compare(const CompareArgs& args) {
  exporters::CompareOptions o;
  o.max_mean_diff = args.max_mean_diff;
  o.max_region_diff = args.max_region_diff;
  o.max_layer_diff = args.max_layer_diff;
  o.max_normal_deg = args.max_normal_deg;
  o.alpha = args.alpha;
  o.statistical = args.statistical;
  const exporters::SetComparison c = exporters::compare_image_sets(args.set_a, args.set_b, o);
  if (!args.out.empty()) exporters::write_compare_reports(c, o, args.set_a, args.set_b, args.out);
  std::size_t failed = 0;
  for (const exporters::ImageDifference& d : c.images) failed += d.pass ? 0 : 1;
  if (args.json) {
    std::cout << exporters::comparison_json(c) << "\n";
  } else {
    for (const exporters::ImageDifference& d : c.images)
      if (d.noise.available)
        std::cout << fmt::format(
            "{} f{}: {} (image z = {:.2f}, worst region z = {:.2f}; limits "
            "{:.2f} and {:.2f} at alpha {})\n",
            d.view, d.frame,
            d.noise.within_noise ? "within the renders' noise"
                                 : "differs by more than the renders' noise",
            d.noise.image_z, d.noise.region_max_z, d.noise.image_threshold,
            d.noise.region_threshold, args.alpha);
    for (const exporters::ImageDifference& d : c.images)
      if (!d.pass)
        std::cout << fmt::format(
            "{} f{}: {}mean luminance {:.3f}%, worst region {:.3f}%, depth {:.3f}%, normals "
            "{:.2f} deg, object {:.3f}%, species {:.3f}%\n",
            d.view, d.frame, d.size_mismatch ? "sizes differ; " : "",
            100 * d.luminance_mean_rel_diff, 100 * d.luminance_region_max_rel_diff,
            100 * d.depth_mean_rel_diff, d.normal_mean_angle_deg, 100 * d.object_mismatch,
            100 * d.species_mismatch);
    for (const std::string& k : c.only_in_a) std::cout << k << ": only in " << args.set_a << "\n";
    for (const std::string& k : c.only_in_b) std::cout << k << ": only in " << args.set_b << "\n";
    std::cout << fmt::format(
        "{}: {} images compared, {} differ past the thresholds, {} only in "
        "one set\n",
        c.pass ? "pass" : "FAIL", c.images.size(), failed, c.only_in_a.size() + c.only_in_b.size());
  }
  return c.pass ? 0 : kCrosscheckFailed;
}

}  // namespace landsim::app
