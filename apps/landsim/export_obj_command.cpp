#include "export_obj_command.h"

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include <iostream>

#include "exporters/obj_export.h"
#include "scenario_input.h"
#include "scenes/builder/scene_builder.h"

namespace landsim::app {

CLI::App* add_export_obj_command(CLI::App& app, ExportObjArgs& args) {
  CLI::App* cmd = app.add_subcommand(
      "export-obj",
      "Write a scenario's scene as OBJ: the ground, each tree prototype once, and the trees' "
      "placements in <out>.instances.csv");
  cmd->add_option("scenario", args.scenario, "Scenario TOML file (default: the embedded scene)");
  cmd->add_option("--out", args.out, "OBJ file")->required();
  cmd->add_option("--view", args.view,
                  "The view whose camera chooses the nearest trees (default: the first)");
  cmd->add_option("--max-trees", args.max_trees,
                  "Only the N trees nearest the view (0: the ground alone; default: every tree)");
  cmd->add_flag("--flatten", args.flatten,
                "Write every tree's triangles into the OBJ (for renderers without instancing)");
  cmd->add_option("--frame", args.frame,
                  "terrain: the terrain's own coordinates; scene: less the scene origin (the "
                  "grid's centre), as landsim renders")
      ->check(CLI::IsMember({"terrain", "scene"}))
      ->capture_default_str();
  cmd->add_flag("--print-pathtracer", args.print_pathtracer,
                "Print only the command line of Embree's pathtracer tutorial for this OBJ and "
                "camera (with --flatten --frame scene; used by bench/embree_pathtracer.sh)");
  add_set_option(*cmd, args.sets);
  return cmd;
}

int run_export_obj(const ExportObjArgs& args) {
  const scenes::Scenario scenario = scenario_or_default(args.scenario, args.sets);
  const renderer::Scene scene = scenes::build_scene(scenario);
  const renderer::View& v = scene.views[view_index(scenario, args.view)];
  exporters::SceneObjOptions o;
  if (args.max_trees) o.max_trees = *args.max_trees;
  o.near = v.position;
  o.flatten = args.flatten;
  o.terrain_frame = args.frame == "terrain";
  const exporters::SceneObjSummary s = exporters::write_scene_obj(scene, args.out, o);
  if (args.print_pathtracer) {
    // The same camera for Embree's pathtracer tutorial (the OBJ's frame).
    const Vec3 shift = o.terrain_frame ? scene.origin : Vec3{};
    const Vec3 p = v.position + shift, t = v.target + shift;
    std::cout << fmt::format(
        "pathtracer -i {} --vp {} {} {} --vi {} {} {} --vu 0 0 1 --fov {} --size {} {}\n", args.out,
        p.x, p.y, p.z, t.x, t.y, t.z, v.fov_y_deg, v.width, v.height);
    return 0;
  }
  std::cout << fmt::format("{}: {:.1f} MB, {} frame: ground ({} triangles), ", args.out,
                           static_cast<double>(s.bytes) / 1e6, args.frame, s.ground_triangles);
  if (!scene.objects.empty())
    std::cout << fmt::format("{} objects in place ({} triangles), ", scene.objects.size(),
                             s.object_triangles);
  if (args.flatten) {
    std::cout << fmt::format("{} trees flattened ({} triangles)\n", s.instances, s.tree_triangles);
  } else {
    std::cout << fmt::format("{} tree prototypes once ({} triangles), {} instances in {}\n",
                             s.prototypes, s.tree_triangles, s.instances,
                             s.instances_file.string());
  }
  return 0;
}

}  // namespace landsim::app
