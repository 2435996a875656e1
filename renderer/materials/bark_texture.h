#pragma once
// A bark texture: an image (anything OpenImageIO reads, converted to linear RGB) wrapped
// around stems, u once around, v along the stem in base circumferences. It modulates the
// species' bark albedo, normalised so the albedo stays the mean.
#include <memory>
#include <string>
#include <vector>

#include "core/vec3.h"
#include "renderer/materials/texture_image.h"

namespace landsim::renderer {

class BarkTexture {
 public:
  // Divides the image by its mean luminance.
  explicit BarkTexture(TextureImage image);
  // Bilinear, wrapping in both directions.
  Vec3f factor(float u, float v) const;

 private:
  TextureImage image_;  // linear, normalised
};

// Throws InputError naming the file, and `what` it was read as, when it cannot be read
// (the ground's textures are read as this type too).
std::shared_ptr<const BarkTexture> load_bark_texture(const std::string& path,
                                                     const std::string& what = "bark texture");

}  // namespace landsim::renderer
