#include "scenes/starter_scenario.h"

namespace landsim::scenes {

// Generated at build time (cmake/EmbedFile.cmake).
extern const std::string_view kStarterScenarioToml;
extern const std::string_view kStarterClassesToml;
extern const std::string_view kVolcanoAsc;
extern const std::string_view kVolcanoLandcoverAsc;
extern const std::string_view kQuakingAspenToml;
extern const std::string_view kCaBlackOakToml;

std::vector<std::pair<std::string, std::string_view>> starter_files() {
  return {{"scenario.toml", kStarterScenarioToml},
          {"classes.toml", kStarterClassesToml},
          {"data/volcano.asc", kVolcanoAsc},
          {"data/landcover.asc", kVolcanoLandcoverAsc},
          {"species/quaking_aspen.toml", kQuakingAspenToml},
          {"species/ca_black_oak.toml", kCaBlackOakToml}};
}

}  // namespace landsim::scenes
