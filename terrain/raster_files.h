#pragma once
// File access through GDAL's virtual file system, so that embedded data (held in memory under
// /vsimem/) and files on disk are named and checked the same way.
#include <string>
#include <string_view>

namespace landsim::terrain {

// Registers GDAL's drivers once; safe to call from anywhere.
void ensure_gdal_registered();

// Makes `bytes` readable at the GDAL path `vsi_path` (normally under /vsimem/). The bytes are
// not copied and must outlive every read; idempotent for the same path.
void mount_memory_file(const std::string& vsi_path, std::string_view bytes);

// True when a regular file (on disk or in GDAL's virtual file system) exists at `path`.
bool raster_file_exists(const std::string& path);

}  // namespace landsim::terrain
