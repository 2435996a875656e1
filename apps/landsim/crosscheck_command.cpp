#include "crosscheck_command.h"

#include <fmt/format.h>
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <iostream>

#include "core/input_error.h"
#include "exporters/crosscheck.h"
#include "scenario_input.h"
#include "scenes/scenario/render_choices.h"
#include "scenes/builder/scene_builder.h"

namespace landsim::app {

CLI::App* add_crosscheck_command(CLI::App& app, CrosscheckArgs& args) {
  CLI::App* cmd = app.add_subcommand(
      "crosscheck", "Render with landsim and POV-Ray and compare (docs/CROSSCHECK.md)");
  add_scene_view_options(*cmd, args.scenario, args.out, args.view);
  add_spp_option(*cmd, args.spp, "Samples per pixel for both");
  add_size_options(*cmd, args.width, args.height);
  cmd->add_option("--threads", args.threads, "landsim worker threads (0: every core)")
      ->check(CLI::Range(0, 1024));
  cmd->add_option("--min-iou", args.min_iou, "Least object IoU that passes")
      ->check(CLI::Range(0.0, 1.0))
      ->capture_default_str();
  cmd->add_option("--max-mean-diff", args.max_mean_diff,
                  "Largest mean relative luminance difference that passes")
      ->check(CLI::Range(0.0, 10.0))
      ->capture_default_str();
  cmd->add_option("--max-region-diff", args.max_region_diff,
                  "Largest per-region relative luminance difference")
      ->check(CLI::Range(0.0, 10.0))
      ->capture_default_str();
  cmd->add_flag("--json", args.json, "Print one JSON object on stdout");
  cmd->add_option("--reference", args.reference,
                  "Compare with this image instead of running POV-Ray (float files in cd/m2, "
                  "8-bit ones at the export's exposure)")
      ->check(CLI::ExistingFile);
  cmd->add_option("--mask", args.mask, "The reference's class mask (LS_Mask's colours)")
      ->check(CLI::ExistingFile);
  cmd->add_option("--align", args.align,
                  "Search translations of the reference up to this many pixels first")
      ->check(CLI::Range(0, 16));
  cmd->add_option("--pov", args.pov,
                  "Render this POV-Ray scene with POV-Ray and landsim at its camera, and compare")
      ->check(CLI::ExistingFile)
      ->excludes("--reference");
  add_set_option(*cmd, args.sets);
  return cmd;
}

int run_crosscheck(const CrosscheckArgs& args) {
  scenes::Scenario s = scenario_or_default(args.scenario, args.sets);
  scenes::override_view_sizes(s, args.width, args.height);
  const renderer::Scene scene = scenes::build_scene(s);
  exporters::CrosscheckOptions o;
  o.out_dir = args.out;
  o.view = view_index(s, args.view);
  o.spp = args.spp;
  o.threads = args.threads;
  o.min_iou = args.min_iou;
  o.max_mean_diff = args.max_mean_diff;
  o.max_region_diff = args.max_region_diff;
  o.reference = args.reference;
  o.mask = args.mask;
  o.align = args.align;
  o.pov_scene = args.pov;
  if (!o.mask.empty() && o.reference.empty())
    throw InputError("crosscheck --mask: only with --reference (POV-Ray makes its own mask)");
  const exporters::CrosscheckReport r = exporters::crosscheck(s, scene, o);
  if (args.json) {
    nlohmann::json j{{"object_iou", r.object_iou},
                     {"luminance_mean_rel_diff", r.luminance_mean_rel_diff},
                     {"luminance_region_max_rel_diff", r.luminance_region_max_rel_diff},
                     {"landsim_seconds", r.landsim_seconds},
                     {"povray_seconds", r.povray_seconds},
                     {"pass", r.pass}};
    if (r.scene_object_iou) j["scene_object_iou"] = *r.scene_object_iou;
    if (r.shift) j["shift"] = *r.shift;
    if (r.camera) j["camera"] = exporters::camera_json(r.camera);
    std::cout << j.dump() << "\n";
  } else {
    std::cout << fmt::format(
        "{}: object IoU {:.4f}, mean luminance difference {:.2f}%, worst region {:.2f}%; "
        "landsim {:.2f} s, POV-Ray {:.2f} s; report in {}/report.html\n",
        r.pass ? "pass" : "FAIL", r.object_iou, 100 * r.luminance_mean_rel_diff,
        100 * r.luminance_region_max_rel_diff, r.landsim_seconds, r.povray_seconds, args.out);
  }
  return r.pass ? 0 : kCrosscheckFailed;
}

}  // namespace landsim::app
