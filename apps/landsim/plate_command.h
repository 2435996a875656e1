#pragma once
// `landsim plate SPECIES_FILE --out FILE.png [--ranges 30,60,...] [--season S]
//  [--quality Q] [--evergreen] [--seed N] [--tile PIXELS] [--spp N]`: Weber & Penn's Plate 4,
// one tree at each range's degradation, every panel framed alike, labelled with the range.
#include <cstdint>
#include <string>

#include "degraded_tree.h"

namespace CLI {
class App;
}

namespace landsim::app {

struct PlateArgs {
  DegradedTreeArgs tree{"", {30, 60, 120, 240, 600, 1200}};
  std::string out;
  int tile = 320;
  int spp = 16;
};

CLI::App* add_plate_command(CLI::App& app, PlateArgs& args);
int run_plate(const PlateArgs& args);

}  // namespace landsim::app
