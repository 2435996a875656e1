#pragma once
// Files the scenario names (rasters, species and class-map files), whether embedded in the
// program (the default scene's, held in memory under /vsimem/landsim/) or on disk, named and
// checked the same way. Paths in GDAL's other virtual file systems (/vsizip/, /vsicurl/...)
// are asked of GDAL (terrain/raster_io.h); everything else is read without it.
#include <optional>
#include <string>
#include <string_view>

namespace landsim::terrain {

// Makes `bytes` readable at `vsi_path` (normally under /vsimem/). The bytes are not copied
// and must outlive every read; idempotent for the same path.
void mount_memory_file(const std::string& vsi_path, std::string_view bytes);

// The whole content of a file in memory, on disk or in GDAL's virtual file systems; empty
// optional when it cannot be read.
std::optional<std::string> read_text_file(const std::string& path);

// True when a regular file exists at `path` (in memory, on disk or in GDAL's virtual file
// systems).
bool raster_file_exists(const std::string& path);

// Before GDAL opens `path`: an in-memory file is handed to GDAL (mounted under its path).
void share_with_gdal(const std::string& path);

}  // namespace landsim::terrain
