#pragma once
// File access through GDAL's virtual file system, so that embedded data (held in memory under
// /vsimem/) and files on disk are named and checked the same way.
#include <optional>
#include <string>
#include <string_view>

namespace landsim::terrain {

// Registers GDAL's drivers once; safe to call from anywhere.
void ensure_gdal_registered();

// Makes `bytes` readable at the GDAL path `vsi_path` (normally under /vsimem/). The bytes are
// not copied and must outlive every read; idempotent for the same path.
void mount_memory_file(const std::string& vsi_path, std::string_view bytes);

// The whole content of a file on disk or in GDAL's virtual file system; empty optional when
// it cannot be read.
std::optional<std::string> read_text_file(const std::string& path);

// True when a regular file (on disk or in GDAL's virtual file system) exists at `path`.
bool raster_file_exists(const std::string& path);

}  // namespace landsim::terrain
