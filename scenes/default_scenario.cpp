#include "scenes/default_scenario.h"

#include <string>
#include <string_view>

#include "terrain/raster_files.h"

namespace landsim::scenes {

// Generated at build time (cmake/EmbedFile.cmake).
extern const std::string_view kDefaultScenarioToml;
extern const std::string_view kVolcanoClassesToml;
extern const std::string_view kVolcanoAsc;
extern const std::string_view kVolcanoLandcoverAsc;
extern const std::string_view kQuakingAspenToml;
extern const std::string_view kCaBlackOakToml;

namespace {
// The embedded files appear under /vsimem/ at the paths they have in the repository, so the
// scenario's relative path to its elevation grid resolves the same way in both places.
constexpr const char* kVirtualRoot = "/vsimem/landsim";
}  // namespace

Scenario default_scenario() {
  const std::string root = kVirtualRoot;
  terrain::mount_memory_file(root + "/data/terrain/volcano.asc", kVolcanoAsc);
  terrain::mount_memory_file(root + "/data/featuremaps/volcano_landcover.asc",
                             kVolcanoLandcoverAsc);
  terrain::mount_memory_file(root + "/data/species/quaking_aspen.toml", kQuakingAspenToml);
  terrain::mount_memory_file(root + "/data/species/ca_black_oak.toml", kCaBlackOakToml);
  terrain::mount_memory_file(root + "/scenes/examples/volcano_classes.toml", kVolcanoClassesToml);
  return parse_scenario(kDefaultScenarioToml, kDefaultScenarioName, root + "/scenes/examples");
}

}  // namespace landsim::scenes
