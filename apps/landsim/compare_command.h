#pragma once
// `landsim compare SET_A SET_B [--out DIR] [--json] [--max-mean-diff X]
//                  [--max-region-diff X] [--max-layer-diff X] [--max-normal-deg X]`:
// two image sets written by `landsim render`, image by image (docs/CROSSCHECK.md).
#include <string>

namespace CLI {
class App;
}

namespace landsim::app {

struct CompareArgs {
  std::string set_a, set_b;
  std::string out;  // empty: no report files
  double max_mean_diff = 0.01;
  double max_region_diff = 0.05;
  double max_layer_diff = 0.01;
  double max_normal_deg = 1.0;
  double alpha = 0.001;
  bool statistical = false;
  bool json = false;
};

CLI::App* add_compare_command(CLI::App& app, CompareArgs& args);
// 0 when the sets agree, 3 (as a failed cross-check) when they do not.
int run_compare(const CompareArgs& args);

}  // namespace landsim::app
