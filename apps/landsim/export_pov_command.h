#pragma once
// `landsim export-pov SCENARIO --out DIR [--view NAME] [--frame N]`
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace landsim::app {

struct ExportPovArgs {
  std::vector<std::string> sets;  // --set key=value overrides
  std::string scenario;
  std::string out;
  std::string view;
  int frame = 0;
};

CLI::App* add_export_pov_command(CLI::App& app, ExportPovArgs& args);
int run_export_pov(const ExportPovArgs& args);

}  // namespace landsim::app
