#include "featuremap_command.h"

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include <iostream>

#include "featuremaps/class_mapping.h"
#include "featuremaps/vegetation_map.h"
#include "terrain/dem_loader.h"

namespace landsim::app {

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
