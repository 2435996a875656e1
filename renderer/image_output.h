#pragma once
// Writing films: a linear OpenEXR (RGB plus depth and normal layers, with metadata) and an
// 8-bit sRGB preview PNG. Both are written under a temporary name and renamed when complete.
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "renderer/film.h"

namespace landsim::renderer {

using ImageMetadata = std::vector<std::pair<std::string, std::string>>;

// Channels: R, G, B (radiance), Z (depth, metres; infinity for sky), N.X, N.Y, N.Z (normal),
// all 32-bit float; string attributes under "landsim/<key>".
void write_exr(const Film& film, const std::filesystem::path& path, const ImageMetadata& metadata);

// Scales by 2^exposure_ev, converts linear to sRGB (OpenImageIO), writes 8-bit PNG.
void write_preview_png(const Film& film, const std::filesystem::path& path, double exposure_ev);

}  // namespace landsim::renderer
