#pragma once
// `landsim grow SPECIES --ages 10,20,30 --out DIR`: one tree of any core's species at several
// ages (the measured-growth paper's Figure 3 for every core): one image per age under the
// same camera, with a person-sized figure for scale and the age written in it, and
// growth.json: the model's measured dimensions, stems and leaves per age (beside the
// equations' for measured growth).
#include <cstdint>
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace landsim::app {

struct GrowArgs {
  std::string species;
  std::vector<double> ages;  // empty: the core's defaults
  std::string out;
  std::uint64_t seed = 1;
  int width = 480;
  int height = 480;
  int spp = 16;
  bool json = false;
  bool cutaway = false;  // ground only behind the trees: roots below it show
};

CLI::App* add_grow_command(CLI::App& app, GrowArgs& args);
int run_grow(const GrowArgs& args);

}  // namespace landsim::app
