#include "renderer/materials/bark_texture.h"

namespace landsim::renderer {

BarkTexture::BarkTexture(TextureImage image) : image_(std::move(image)) {
  const double mean = image_.mean_luminance();
  image_.scale(static_cast<float>(mean > 0.0 ? 1.0 / mean : 1.0));
}

Vec3f BarkTexture::factor(float u, float v) const {
  return image_.bilinear(u * static_cast<float>(image_.width()) - 0.5f,
                         v * static_cast<float>(image_.height()) - 0.5f);
}

std::shared_ptr<const BarkTexture> load_bark_texture(const std::string& path,
                                                     const std::string& what) {
  return std::make_shared<const BarkTexture>(load_texture_image(path, what));
}

}  // namespace landsim::renderer
