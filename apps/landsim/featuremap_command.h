#pragma once
// `landsim featuremap build CLASSES --map MAP --out VEG.tif [--seed N]`
#include <cstdint>
#include <string>

namespace CLI {
class App;
}

namespace landsim::app {

struct FeaturemapBuildArgs {
  std::string classes;
  std::string map;
  std::string out;
  std::uint64_t seed = 1;
};

CLI::App* add_featuremap_command(CLI::App& app, FeaturemapBuildArgs& args);
int run_featuremap_build(const FeaturemapBuildArgs& args);

}  // namespace landsim::app
