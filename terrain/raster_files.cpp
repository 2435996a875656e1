#include "terrain/raster_files.h"

#include <cpl_vsi.h>
#include <gdal.h>

#include <mutex>

namespace landsim::terrain {

void ensure_gdal_registered() {
  static std::once_flag once;
  std::call_once(once, [] { GDALAllRegister(); });
}

void mount_memory_file(const std::string& vsi_path, std::string_view bytes) {
  static std::mutex mutex;
  const std::lock_guard lock(mutex);
  if (raster_file_exists(vsi_path)) return;
  // GDAL only reads the buffer (bTakeOwnership = FALSE), so the const_cast is safe.
  auto* data = reinterpret_cast<GByte*>(const_cast<char*>(bytes.data()));
  VSILFILE* f = VSIFileFromMemBuffer(vsi_path.c_str(), data, bytes.size(), FALSE);
  if (f != nullptr) VSIFCloseL(f);
}

std::optional<std::string> read_text_file(const std::string& path) {
  if (!raster_file_exists(path)) return std::nullopt;
  VSILFILE* f = VSIFOpenL(path.c_str(), "rb");
  if (f == nullptr) return std::nullopt;
  std::string text;
  char buffer[65536];
  std::size_t n = 0;
  while ((n = VSIFReadL(buffer, 1, sizeof buffer, f)) > 0) text.append(buffer, n);
  VSIFCloseL(f);
  return text;
}

bool raster_file_exists(const std::string& path) {
  VSIStatBufL stat{};
  return VSIStatL(path.c_str(), &stat) == 0 && VSI_ISREG(stat.st_mode);
}

}  // namespace landsim::terrain
