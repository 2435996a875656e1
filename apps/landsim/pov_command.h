#pragma once
// `landsim export-pov SCENARIO --out DIR [--view NAME] [--frame N]` and
// `landsim crosscheck SCENARIO --out DIR [--view NAME] [--spp N] [--min-iou X]
//                     [--max-mean-diff X] [--max-region-diff X] [--json]`
#include <string>

namespace CLI {
class App;
}

namespace landsim::app {

struct PovArgs {
  std::string scenario;
  std::string out;
  std::string view;
  int frame = 0;
  int spp = 16;
  int threads = 0;
  double min_iou = 0.98;
  double max_mean_diff = 0.05;
  double max_region_diff = 0.25;
  bool json = false;
};

// Exit code of a cross-check that ran but did not pass.
inline constexpr int kCrosscheckFailed = 3;

CLI::App* add_export_pov_command(CLI::App& app, PovArgs& args);
CLI::App* add_crosscheck_command(CLI::App& app, PovArgs& args);
int run_export_pov(const PovArgs& args);
int run_crosscheck(const PovArgs& args);

}  // namespace landsim::app
