#pragma once
// `landsim grow SPECIES --ages 10,20,30 --out DIR`: a measured-growth species at several ages
// (the seed paper's Figure 3): one image per age under the same camera, with a person-sized
// figure for scale, and growth.json: the model's measured dimensions beside the equations'.
#include <cstdint>
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace landsim::app {

struct GrowArgs {
  std::string species;
  std::vector<double> ages{10, 20, 30, 40, 50};
  std::string out;
  std::uint64_t seed = 1;
  int width = 480;
  int height = 480;
  int spp = 16;
  bool json = false;
};

CLI::App* add_grow_command(CLI::App& app, GrowArgs& args);
int run_grow(const GrowArgs& args);

}  // namespace landsim::app
