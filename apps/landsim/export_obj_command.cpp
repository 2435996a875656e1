#include "export_obj_command.h"

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include <iostream>

#include "exporters/obj_export.h"
#include "scenario_input.h"
#include "scenes/scene_builder.h"

namespace landsim::app {

CLI::App* add_export_obj_command(CLI::App& app, ExportObjArgs& args) {
  CLI::App* cmd = app.add_subcommand(
      "export-obj", "Write a scenario's scene (ground and nearest trees) as one OBJ");
  cmd->add_option("scenario", args.scenario, "Scenario TOML file (default: the embedded scene)");
  cmd->add_option("--out", args.out, "OBJ file")->required();
  cmd->add_option("--max-trees", args.max_trees,
                  "Trees nearest the first view to include, flattened")
      ->capture_default_str();
  return cmd;
}

int run_export_obj(const ExportObjArgs& args) {
  const scenes::Scenario scenario = scenario_or_default(args.scenario);
  const renderer::Scene scene = scenes::build_scene(scenario);
  const renderer::View& v = scene.views.front();
  exporters::write_scene_obj(scene, args.out, args.max_trees, v.position);
  // The same camera for Embree's pathtracer tutorial (scene frame).
  std::cout << fmt::format(
      "pathtracer -i {} --vp {} {} {} --vi {} {} {} --vu 0 0 1 --fov {} --size {} {}\n", args.out,
      v.position.x, v.position.y, v.position.z, v.target.x, v.target.y, v.target.z, v.fov_y_deg,
      v.width, v.height);
  return 0;
}

}  // namespace landsim::app
