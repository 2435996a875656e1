#include "scenes/scenario/starter_scenario.h"

#include "scenes/scenario/detail/embedded_files.h"

namespace landsim::scenes {

std::vector<std::pair<std::string, std::string_view>> starter_files() {
  return {{"scenario.toml", kStarterScenarioToml},
          {"classes.toml", kStarterClassesToml},
          {"data/volcano.asc", kVolcanoAsc},
          {"data/landcover.asc", kVolcanoLandcoverAsc},
          {"species/quaking_aspen.toml", kQuakingAspenToml},
          {"species/ca_black_oak.toml", kCaBlackOakToml}};
}

}  // namespace landsim::scenes
