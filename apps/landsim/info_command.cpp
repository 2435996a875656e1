#include "info_command.h"

#include <fmt/format.h>
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <iostream>

#include "exporters/obj_export.h"
#include "featuremaps/class_mapping.h"
#include "scenes/default_scenario.h"
#include "scenes/memory_estimate.h"
#include "scenes/scene_builder.h"
#include "terrain/dem_loader.h"

namespace landsim::app {

CLI::App* add_info_command(CLI::App& app, InfoArgs& args) {
  CLI::App* cmd = app.add_subcommand(
      "info", "Describe a scenario's scene without building it: expected trees, triangles, memory");
  cmd->add_option("scenario", args.scenario, "Scenario TOML file (default: the embedded scene)");
  cmd->add_flag("--json", args.json, "Print one JSON object on stdout");
  return cmd;
}

int run_info(const InfoArgs& args) {
  const scenes::Scenario scenario =
      args.scenario.empty() ? scenes::default_scenario() : scenes::load_scenario(args.scenario);
  const scenes::MemoryEstimate e = scenes::estimate_memory(scenario);
  const auto count = [](double n) { return static_cast<std::size_t>(std::llround(n)); };
  if (args.json) {
    nlohmann::json per_species = nlohmann::json::object();
    std::size_t instances = 0;  // the sum of the species' rounded counts
    for (const auto& [name, n] : e.instances_per_species) {
      per_species[name] = count(n);
      instances += count(n);
    }
    nlohmann::json parts = nlohmann::json::object();
    for (const scenes::MemoryPart& p : e.parts) parts[p.name] = p.bytes;
    parts["program"] = e.program_bytes;
    std::cout << nlohmann::json{{"instances", instances},
                                {"instances_per_species", per_species},
                                {"unique_variants", e.unique_variants},
                                {"triangles_stored", count(e.triangles_stored)},
                                {"triangles_instanced", count(e.triangles_instanced)},
                                {"grass_tiles", e.grass_tiles},
                                {"grass_patches_drawn", e.grass_patches_drawn},
                                {"memory_estimate_bytes", e.total_bytes()},
                                {"memory_parts_bytes", parts},
                                // The image set: what a job array needs to size itself.
                                {"views", scenario.views.size()},
                                {"frames", scenario.render.frames.size()},
                                {"images", scenario.views.size() * scenario.render.frames.size()}}
                     .dump()
              << "\n";
    return 0;
  }
  std::cout << fmt::format("{}\n  trees (expected)    {}\n", scenario.source, count(e.instances));
  for (const auto& [name, n] : e.instances_per_species)
    std::cout << fmt::format("    {:<20}{}\n", name, count(n));
  std::cout << fmt::format(
      "  unique variants     {}\n  triangles stored    {}\n  triangles instanced {}\n"
      "  grass tiles         {}\n  memory estimate     {:.0f} MB at the peak\n",
      e.unique_variants, count(e.triangles_stored), count(e.triangles_instanced), e.grass_tiles,
      static_cast<double>(e.total_bytes()) / 1e6);
  std::cout << fmt::format("    {:<38}{:>6.0f} MB\n", "program",
                           static_cast<double>(e.program_bytes) / 1e6);
  for (const scenes::MemoryPart& p : e.parts)
    std::cout << fmt::format("    {:<38}{:>6.0f} MB\n", p.name, static_cast<double>(p.bytes) / 1e6);
  return 0;
}

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
  const scenes::Scenario scenario =
      args.scenario.empty() ? scenes::default_scenario() : scenes::load_scenario(args.scenario);
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

CLI::App* add_featuremap_command(CLI::App& app, FeaturemapBuildArgs& args) {
  CLI::App* fm = app.add_subcommand("featuremap", "Feature-map tools");
  fm->require_subcommand(1);
  CLI::App* build =
      fm->add_subcommand("build", "Turn a land-cover class raster into a 16-bit vegetation map");
  build->add_option("classes", args.classes, "Class raster (any format GDAL reads)")->required();
  build->add_option("--map", args.map, "Class mapping TOML ([[class]] value, species, grass)")
      ->required();
  build->add_option("--out", args.out, "Output UInt16 GeoTIFF")->required();
  build->add_option("--seed", args.seed, "Seed of the per-cell species choice")
      ->capture_default_str();
  return build;
}

int run_featuremap_build(const FeaturemapBuildArgs& args) {
  const terrain::ElevationGrid classes = terrain::load_elevation(args.classes);
  const featuremaps::ClassMapping mapping = featuremaps::load_class_mapping(args.map);
  const featuremaps::VegetationMap map =
      featuremaps::build_vegetation_map(classes, mapping, args.seed);
  featuremaps::write_vegetation_map(map, args.out, classes.crs_wkt());
  std::cout << fmt::format("{}: {} x {} cells, {} with multiple species bits\n", args.out,
                           map.cols(), map.rows(), map.multi_species_cells());
  return 0;
}

}  // namespace landsim::app
