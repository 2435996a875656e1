#include "terrain/raster_files.h"

#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <sstream>

#include "terrain/raster_io.h"

namespace landsim::terrain {
namespace {

// The in-memory files, by path.
class MemoryFiles {
 public:
  void add(const std::string& path, std::string_view bytes) {
    const std::lock_guard lock(mutex_);
    files_.emplace(path, bytes);
  }
  std::optional<std::string_view> find(const std::string& path) const {
    const std::lock_guard lock(mutex_);
    const auto it = files_.find(path);
    if (it == files_.end()) return std::nullopt;
    return it->second;
  }

 private:
  mutable std::mutex mutex_;
  std::map<std::string, std::string_view> files_;
};

MemoryFiles& memory_files() {
  static MemoryFiles files;
  return files;
}

// GDAL's virtual file systems are named by a /vsi prefix.
bool is_gdal_virtual(const std::string& path) { return path.rfind("/vsi", 0) == 0; }

}  // namespace

void mount_memory_file(const std::string& vsi_path, std::string_view bytes) {
  memory_files().add(vsi_path, bytes);
}

std::optional<std::string> read_text_file(const std::string& path) {
  if (const auto bytes = memory_files().find(path)) return std::string(*bytes);
  if (is_gdal_virtual(path)) {
    std::string bytes;  // a species file inside a zip, say
    if (!raster_io().read_file(path, bytes)) return std::nullopt;
    return bytes;
  }
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) return std::nullopt;
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

bool raster_file_exists(const std::string& path) {
  if (memory_files().find(path)) return true;
  if (is_gdal_virtual(path)) return raster_io().file_exists(path);
  std::error_code ec;
  return std::filesystem::is_regular_file(path, ec);
}

void share_with_gdal(const std::string& path) {
  if (const auto bytes = memory_files().find(path)) raster_io().mount_memory_file(path, *bytes);
}

}  // namespace landsim::terrain
