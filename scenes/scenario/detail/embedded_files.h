#pragma once
// The files compiled into the program (scenes/CMakeLists.txt, cmake/EmbedFile.cmake): the
// default scenario and every file it reads, and the starter scenario of `landsim init`.
#include <string_view>

namespace landsim::scenes {

extern const std::string_view kDefaultScenarioToml;
extern const std::string_view kVolcanoClassesToml;
extern const std::string_view kVolcanoAsc;
extern const std::string_view kVolcanoLandcoverAsc;
extern const std::string_view kQuakingAspenToml;
extern const std::string_view kCaBlackOakToml;
extern const std::string_view kStarterScenarioToml;
extern const std::string_view kStarterClassesToml;

}  // namespace landsim::scenes
