#pragma once
// `landsim degrade SPECIES_FILE [--ranges 5,30,...] [--season S] [--quality Q] [--height H]
//  [--fov F] [--paper] [--evergreen] [--seed N] [--json]`: Weber & Penn's Table 2 for one
// tree: how many triangles, lines and points range degradation draws at each range.
#include "degraded_tree.h"

namespace CLI {
class App;
}

namespace landsim::app {

struct DegradeArgs {
  DegradedTreeArgs tree{"", {5, 30, 60, 120, 240, 600, 1200}};
  int height = 1080;
  double fov = 40.0;
  bool paper = false;  // the paper's calibration: 1000 pixels, 60 degrees (r2 = range)
  bool json = false;
};

CLI::App* add_degrade_command(CLI::App& app, DegradeArgs& args);
int run_degrade(const DegradeArgs& args);

}  // namespace landsim::app
