#pragma once
// `landsim crosscheck SCENARIO --out DIR [--view NAME] [--spp N] [--min-iou X]
//                     [--max-mean-diff X] [--max-region-diff X] [--json]
//                     [--reference IMAGE [--mask MASK] [--align N] | --pov FILE.pov]`
#include <optional>
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace landsim::app {

struct CrosscheckArgs {
  std::vector<std::string> sets;  // --set key=value overrides
  std::string scenario;
  std::string out;
  std::string view;
  int spp = 16;
  int threads = 0;
  std::optional<int> width, height;
  double min_iou = 0.98;
  double max_mean_diff = 0.05;
  double max_region_diff = 0.25;
  bool json = false;
  std::string reference, mask;  // a reference image of the user's, and its class mask
  int align = 0;                // pixels of translation searched
  std::string pov;              // a POV-Ray scene of the user's, rendered at its camera
};

// Exit code of a cross-check that ran but did not pass.
inline constexpr int kCrosscheckFailed = 3;

CLI::App* add_crosscheck_command(CLI::App& app, CrosscheckArgs& args);
int run_crosscheck(const CrosscheckArgs& args);

}  // namespace landsim::app
