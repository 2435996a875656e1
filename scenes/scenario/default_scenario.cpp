#include "scenes/scenario/default_scenario.h"

#include <string>
#include <string_view>

#include "scenes/scenario/detail/embedded_files.h"
#include "terrain/raster_files.h"

namespace landsim::scenes {
namespace {
// The embedded files appear under /vsimem/ at the paths they have in the repository, so the
// scenario's relative path to its elevation grid resolves the same way in both places.
constexpr const char* kVirtualRoot = "/vsimem/landsim";
}  // namespace

ScenarioText default_scenario_text() {
  const std::string root = kVirtualRoot;
  terrain::mount_memory_file(root + "/data/terrain/volcano.asc", kVolcanoAsc);
  terrain::mount_memory_file(root + "/data/featuremaps/volcano_landcover.asc",
                             kVolcanoLandcoverAsc);
  terrain::mount_memory_file(root + "/data/species/quaking_aspen.toml", kQuakingAspenToml);
  terrain::mount_memory_file(root + "/data/species/ca_black_oak.toml", kCaBlackOakToml);
  terrain::mount_memory_file(root + "/scenes/examples/volcano_classes.toml", kVolcanoClassesToml);
  return {std::string(kDefaultScenarioToml), kDefaultScenarioName, root + "/scenes/examples"};
}

Scenario default_scenario(const std::vector<std::string>& sets) {
  return parse_scenario(default_scenario_text(), sets);
}

}  // namespace landsim::scenes
