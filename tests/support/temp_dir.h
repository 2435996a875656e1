#pragma once
// Test helpers: a fresh temporary directory per test, removed afterwards, and file I/O.
#include <filesystem>
#include <set>
#include <string>

namespace landsim::testing {

class TempDir {
 public:
  TempDir();
  ~TempDir();
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }
  // Writes `text` to `name` inside the directory and returns the full path.
  std::filesystem::path write(const std::string& name, const std::string& text) const;

 private:
  std::filesystem::path path_;
};

std::string read_file(const std::filesystem::path& path);

// The names of the files (and folders) directly in `dir`: what a command left there,
// temporary files included.
std::set<std::string> file_names(const std::filesystem::path& dir);

// A file in the repository (tests never read outside it).
inline std::filesystem::path source_file(const std::string& relative) {
  return std::filesystem::path(LANDSIM_SOURCE_DIR) / relative;
}

}  // namespace landsim::testing
