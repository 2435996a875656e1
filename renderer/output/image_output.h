#pragma once
// Writing films: one multi-layer OpenEXR per image (RGB radiance plus the AOVs, with
// metadata and camera matrices) and an 8-bit preview PNG through an OpenColorIO display
// transform from the project's own config. Both are written under a temporary name and
// renamed when complete.
#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "renderer/output/film.h"
#include "renderer/output/image_io.h"

namespace landsim::renderer {

using ImageMetadata = std::vector<std::pair<std::string, std::string>>;

// Row-major 4x4 matrices (scene frame; the scene origin goes in the string metadata).
struct CameraMatrices {
  std::array<float, 16> world_to_camera{};
  std::array<float, 16> world_to_ndc{};
  bool has_ndc = false;  // fisheye and spherical images have no linear map to NDC
};

// What the EXR's RGB are (also its "landsim/unit" attribute; whiteLuminance is 1).
inline constexpr const char* kRadianceUnit =
    "scene-linear Rec. 709 radiance; Y = 0.2126 R + 0.7152 G + 0.0722 B is luminance in cd/m2";

// Sensor bands' layers ("band.<name>"): band radiance, the integral of spectral radiance
// times the band's response. A film's band whose name holds a '.' is a layer by that name:
// a sensor channel's photon radiance ("photons.<channel>", photons s-1 m-2 sr-1) or a
// reflectance factor ("reflectance.<band>", docs/SENSOR.md).
std::string band_layer(const std::string& band_name);
inline constexpr const char* kBandUnit = "W m-2 sr-1";
// Channels: R, G, B (radiance, kRadianceUnit); Y (luminance, cd/m2); Z (depth, metres, infinity for
// sky); N.X, N.Y, N.Z (normal); albedo.R, albedo.G, albedo.B; object, species, instance, lod
// (32-bit unsigned; 4294967295 = none). String attributes "landsim/<key>"; OpenEXR's standard
// worldToCamera and worldToNDC when `camera` is given.
// ZIP-compressed, except checkpoints (`compressed` false): they are rewritten every minute
// and deleted at the end, and compressing one cost the render's workers 0.9 s at 1080p.
// Compression runs on every core (OpenEXR's thread pool; the file is the same).
void write_exr(const Film& film, const std::filesystem::path& path, const ImageMetadata& metadata,
               const CameraMatrices* camera = nullptr, bool compressed = true);

// Reads every channel write_exr writes back into a film of the file's size; returns the
// string attributes. Throws std::runtime_error on a file that is not one of ours.
Film read_exr(const std::filesystem::path& path, ImageMetadata* metadata = nullptr);
// Only the metadata of such an EXR (its header; no pixels are read).
ImageMetadata read_exr_metadata(const std::filesystem::path& path);

// Exposes for `ev100` (automatic when empty: renderer/output/exposure.h), then applies the
// OpenColorIO display transform (display sRGB, view Standard) of the project's embedded
// config, draws `labels`, and writes an 8-bit PNG.
// Labels need DejaVu Sans (Debian's fonts-dejavu-core); without it they are left out with a
// warning rather than failing the image.
void write_preview_png(const Film& film, const std::filesystem::path& path,
                       std::optional<double> ev100, const std::vector<ImageLabel>& labels = {});

// The embedded OpenColorIO config (YAML), for users who want to reproduce the preview.
const char* ocio_config_text();

}  // namespace landsim::renderer
