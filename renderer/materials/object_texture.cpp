#include "renderer/materials/object_texture.h"

namespace landsim::renderer {

Vec3f ObjectTexture::colour(float u, float v) const {
  // v counts up from the bottom row; rows are stored top first.
  return image_.bilinear(u * static_cast<float>(image_.width()) - 0.5f,
                         (1.0f - v) * static_cast<float>(image_.height()) - 0.5f);
}

std::shared_ptr<const ObjectTexture> load_object_texture(const std::string& path) {
  return std::make_shared<const ObjectTexture>(load_texture_image(path, "base-colour texture"));
}

}  // namespace landsim::renderer
