#include "renderer/bark_texture.h"

#include <algorithm>
#include <cmath>

#include "core/input_error.h"
#include "renderer/image_io.h"

namespace landsim::renderer {

BarkTexture::BarkTexture(int width, int height, std::vector<float> rgb)
    : width_(width), height_(height), rgb_(std::move(rgb)) {
  double mean = 0.0;
  for (std::size_t i = 0; i + 2 < rgb_.size(); i += 3)
    mean += 0.2126 * rgb_[i] + 0.7152 * rgb_[i + 1] + 0.0722 * rgb_[i + 2];
  mean /= static_cast<double>(width_) * height_;
  const auto scale = static_cast<float>(mean > 0.0 ? 1.0 / mean : 1.0);
  for (float& c : rgb_) c *= scale;
}

Vec3f BarkTexture::texel(int x, int y) const {
  x = ((x % width_) + width_) % width_;
  y = ((y % height_) + height_) % height_;
  const std::size_t i = 3 * (static_cast<std::size_t>(y) * width_ + x);
  return {rgb_[i], rgb_[i + 1], rgb_[i + 2]};
}

Vec3f BarkTexture::factor(float u, float v) const {
  const float x = u * static_cast<float>(width_) - 0.5f, y = v * static_cast<float>(height_) - 0.5f;
  const float fx = std::floor(x), fy = std::floor(y);
  const float tx = x - fx, ty = y - fy;
  const int x0 = static_cast<int>(fx), y0 = static_cast<int>(fy);
  const Vec3f top = texel(x0, y0) * (1.0f - tx) + texel(x0 + 1, y0) * tx;
  const Vec3f bottom = texel(x0, y0 + 1) * (1.0f - tx) + texel(x0 + 1, y0 + 1) * tx;
  return top * (1.0f - ty) + bottom * ty;
}

std::shared_ptr<const BarkTexture> load_bark_texture(const std::string& path) {
  // 8-bit images are sRGB-encoded; float images (EXR) are taken as linear already.
  FloatImage image;
  std::string error;
  if (!image_io().read(path, true, image, error))
    throw InputError(path + ": cannot read bark texture: " + error);
  const int w = image.width, h = image.height, channels = image.channels;
  if (w < 1 || h < 1 || channels < 1) throw InputError(path + ": empty bark texture");
  std::vector<float> rgb(3 * static_cast<std::size_t>(w) * h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < 3; ++c)
        rgb[3 * (static_cast<std::size_t>(y) * w + x) + c] =
            image.at(x, y, std::min(c, channels - 1));
  return std::make_shared<const BarkTexture>(w, h, std::move(rgb));
}

}  // namespace landsim::renderer
