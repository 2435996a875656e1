#pragma once
// `landsim info [SCENARIO] [--json]`: the scene described without building it.
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace landsim::app {

struct InfoArgs {
  std::vector<std::string> sets;  // --set key=value overrides
  std::string scenario;           // empty: the embedded default scene
  bool json = false;
};

CLI::App* add_info_command(CLI::App& app, InfoArgs& args);
int run_info(const InfoArgs& args);

}  // namespace landsim::app
