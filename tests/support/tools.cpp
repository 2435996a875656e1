#include "tests/support/tools.h"

#include <unistd.h>

#include <filesystem>
#include <sstream>
#include <string>

namespace landsim::testing {

bool tool_on_path(const char* name) {
  const char* path = std::getenv("PATH");
  if (path == nullptr) return false;
  std::istringstream folders(path);
  for (std::string folder; std::getline(folders, folder, ':');) {
    if (folder.empty()) continue;
    const std::filesystem::path candidate = std::filesystem::path(folder) / name;
    if (::access(candidate.c_str(), X_OK) == 0 && std::filesystem::is_regular_file(candidate))
      return true;
  }
  return false;
}

}  // namespace landsim::testing
