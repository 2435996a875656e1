#include "renderer/object_texture.h"

#include <algorithm>
#include <cmath>

#include "core/input_error.h"
#include "renderer/image_io.h"

namespace landsim::renderer {

ObjectTexture::ObjectTexture(int width, int height, std::vector<float> rgb)
    : width_(width), height_(height), rgb_(std::move(rgb)) {}

Vec3f ObjectTexture::texel(int x, int y) const {
  x = ((x % width_) + width_) % width_;
  y = ((y % height_) + height_) % height_;
  const std::size_t i = 3 * (static_cast<std::size_t>(y) * width_ + x);
  return {rgb_[i], rgb_[i + 1], rgb_[i + 2]};
}

Vec3f ObjectTexture::colour(float u, float v) const {
  // v counts up from the bottom row; rows are stored top first.
  const float x = u * static_cast<float>(width_) - 0.5f;
  const float y = (1.0f - v) * static_cast<float>(height_) - 0.5f;
  const float fx = std::floor(x), fy = std::floor(y);
  const float tx = x - fx, ty = y - fy;
  const int x0 = static_cast<int>(fx), y0 = static_cast<int>(fy);
  const Vec3f top = texel(x0, y0) * (1.0f - tx) + texel(x0 + 1, y0) * tx;
  const Vec3f bottom = texel(x0, y0 + 1) * (1.0f - tx) + texel(x0 + 1, y0 + 1) * tx;
  return top * (1.0f - ty) + bottom * ty;
}

std::shared_ptr<const ObjectTexture> load_object_texture(const std::string& path) {
  FloatImage image;
  std::string error;
  if (!image_io().read(path, true, image, error))
    throw InputError(path + ": cannot read base-colour texture: " + error);
  const int w = image.width, h = image.height, channels = image.channels;
  if (w < 1 || h < 1 || channels < 1) throw InputError(path + ": empty base-colour texture");
  std::vector<float> rgb(3 * static_cast<std::size_t>(w) * h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < 3; ++c)
        rgb[3 * (static_cast<std::size_t>(y) * w + x) + c] =
            std::max(0.0f, image.at(x, y, std::min(c, channels - 1)));
  return std::make_shared<const ObjectTexture>(w, h, std::move(rgb));
}

}  // namespace landsim::renderer
