#pragma once
// `landsim info [SCENARIO] [--json]` and `landsim featuremap build CLASSES --map MAP --out VEG.tif`
#include <cstdint>
#include <string>

namespace CLI {
class App;
}

namespace landsim::app {

struct InfoArgs {
  std::string scenario;  // empty: the embedded default scene
  bool json = false;
};

struct FeaturemapBuildArgs {
  std::string classes;
  std::string map;
  std::string out;
  std::uint64_t seed = 1;
};

CLI::App* add_info_command(CLI::App& app, InfoArgs& args);
int run_info(const InfoArgs& args);

struct ExportObjArgs {
  std::string scenario;
  std::string out;
  std::size_t max_trees = 0;
};

CLI::App* add_export_obj_command(CLI::App& app, ExportObjArgs& args);
int run_export_obj(const ExportObjArgs& args);

CLI::App* add_featuremap_command(CLI::App& app, FeaturemapBuildArgs& args);
int run_featuremap_build(const FeaturemapBuildArgs& args);

}  // namespace landsim::app
