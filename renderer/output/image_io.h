#pragma once
// Image files other than landsim's EXRs (PNG previews, bark textures, POV-Ray's output)
// through OpenImageIO and OpenColorIO. They live in a module of their own
// (liblandsim_images.so, source in modules/images/) loaded the first time an image is read or
// a PNG written: OpenImageIO alone pulls in over 250 libraries (core/module_loader.h). This is
// the module's function table: plain pixels in and out.
#include <string>
#include <vector>

namespace landsim::renderer {

// Interleaved float pixels, row-major, top row first.
struct FloatImage {
  int width = 0, height = 0, channels = 0;
  std::vector<float> pixels;
  // Read from an integer file (8 or 16 bits: sRGB-encoded, display-referred), not a float one.
  bool display_referred = false;
  float at(int x, int y, int c) const {
    return pixels[(static_cast<std::size_t>(y) * width + x) * channels + c];
  }
};

// White text drawn on a preview, its baseline starting at pixel (x, y).
struct ImageLabel {
  int x = 0, y = 0;
  std::string text;
};

// Every function returns false on failure with OpenImageIO's or OpenColorIO's message in
// `error`.
struct ImageIo {
  // Any format OpenImageIO reads, as float. With `to_linear`, integer images (8 or 16 bits,
  // sRGB-encoded) are converted to linear; float images are taken as linear already.
  // Refuses (false, `error` saying why) an image whose header declares more than 2^28 values
  // before allocating anything.
  bool (*read)(const std::string& path, bool to_linear, FloatImage& image, std::string& error);
  // The header alone: size and channels, with read's refusals; no pixels decoded.
  bool (*probe)(const std::string& path, int& width, int& height, int& channels,
                std::string& error);
  // The display transform (display "sRGB", view "Standard") of the OpenColorIO config
  // `config_yaml`, applied in place to `width` x `height` RGB pixels.
  bool (*display_transform)(const char* config_yaml, float* rgb, int width, int height,
                            std::string& error);
  // An 8-bit PNG of `image` (values 0-1), encoded from linear to sRGB first when
  // `encode_srgb`; `labels` drawn in white in DejaVu Sans (without that font they are left out
  // and `warning` says so).
  bool (*write_png)(const std::string& path, const FloatImage& image, bool encode_srgb,
                    const std::vector<ImageLabel>& labels, std::string& error,
                    std::string& warning);
};

// The module's table, loaded on first use (ModuleError when the module is missing).
const ImageIo& image_io();
// Whether image_io() has loaded the module in this process.
bool image_io_loaded();

// The symbol liblandsim_images.so exports: `const ImageIo* landsim_image_io()`.
inline constexpr const char* kImageIoSymbol = "landsim_image_io";

}  // namespace landsim::renderer
