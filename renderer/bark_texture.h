#pragma once
// A bark texture: an image (anything OpenImageIO reads, converted to linear RGB) wrapped
// around stems, u once around, v along the stem in base circumferences. It modulates the
// species' bark albedo, normalised so the albedo stays the mean.
#include <memory>
#include <string>
#include <vector>

#include "core/vec3.h"

namespace landsim::renderer {

class BarkTexture {
 public:
  BarkTexture(int width, int height, std::vector<float> rgb);
  // Bilinear, wrapping in both directions; divided by the image's mean luminance.
  Vec3f factor(float u, float v) const;

 private:
  Vec3f texel(int x, int y) const;
  int width_, height_;
  std::vector<float> rgb_;  // linear, normalised
};

// Throws InputError naming the file when it cannot be read.
std::shared_ptr<const BarkTexture> load_bark_texture(const std::string& path);

}  // namespace landsim::renderer
