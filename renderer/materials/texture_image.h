#pragma once
// An RGB image for texturing (bark, ground, scene objects): read through the image module
// (8- and 16-bit images sRGB-decoded to linear, float images taken as linear), sampled
// bilinearly, repeating in both directions.
#include <string>
#include <vector>

#include "core/vec3.h"

namespace landsim::renderer {

class TextureImage {
 public:
  TextureImage(int width, int height, std::vector<float> rgb);
  int width() const { return width_; }
  int height() const { return height_; }
  // Bilinear at (x, y) in pixels from the top-left corner, pixel centres at half-integers.
  Vec3f bilinear(float x, float y) const;
  // Every texel times `k` (a normalisation).
  void scale(float k);
  double mean_luminance() const;

 private:
  Vec3f texel(int x, int y) const;
  int width_, height_;
  std::vector<float> rgb_;  // linear, top row first
};

// Throws InputError "`path`: cannot read `what`: ..." when the image cannot be read.
TextureImage load_texture_image(const std::string& path, const std::string& what);

}  // namespace landsim::renderer
