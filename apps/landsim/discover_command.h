#pragma once
// `landsim discover`: trees sampled from the harmonic core's parameter space, rendered as a
// contact sheet (Hoetzlein 2022, Figure 6), each tile's species file written beside it.
#include <cstdint>
#include <string>

namespace CLI {
class App;
}

namespace landsim::app {

struct DiscoverArgs {
  int count = 36;
  std::string out;
  std::uint64_t seed = 1;
  int tile = 256;
  int spp = 16;
  bool json = false;
};

CLI::App* add_discover_command(CLI::App& app, DiscoverArgs& args);
int run_discover(const DiscoverArgs& args);

}  // namespace landsim::app
