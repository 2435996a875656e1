#pragma once
// The starter scenario `landsim init` writes: a commented scenario and every file it reads
// (elevation grid, land cover, class mapping, two species), compiled into the program, as
// paths relative to the folder it goes in.
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace landsim::scenes {

// (relative path, content) of every file, the scenario first.
std::vector<std::pair<std::string, std::string_view>> starter_files();

}  // namespace landsim::scenes
