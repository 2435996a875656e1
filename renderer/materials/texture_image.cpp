#include "renderer/materials/texture_image.h"

#include <algorithm>
#include <cmath>

#include "core/input_error.h"
#include "renderer/output/image_io.h"

namespace landsim::renderer {

TextureImage::TextureImage(int width, int height, std::vector<float> rgb)
    : width_(width), height_(height), rgb_(std::move(rgb)) {}

Vec3f TextureImage::texel(int x, int y) const {
  x = ((x % width_) + width_) % width_;
  y = ((y % height_) + height_) % height_;
  const std::size_t i = 3 * (static_cast<std::size_t>(y) * width_ + x);
  return {rgb_[i], rgb_[i + 1], rgb_[i + 2]};
}

Vec3f TextureImage::bilinear(float x, float y) const {
  const float fx = std::floor(x), fy = std::floor(y);
  const float tx = x - fx, ty = y - fy;
  const int x0 = static_cast<int>(fx), y0 = static_cast<int>(fy);
  const Vec3f top = texel(x0, y0) * (1.0f - tx) + texel(x0 + 1, y0) * tx;
  const Vec3f bottom = texel(x0, y0 + 1) * (1.0f - tx) + texel(x0 + 1, y0 + 1) * tx;
  return top * (1.0f - ty) + bottom * ty;
}

void TextureImage::scale(float k) {
  for (float& c : rgb_) c *= k;
}

double TextureImage::mean_luminance() const {
  double mean = 0.0;
  for (std::size_t i = 0; i + 2 < rgb_.size(); i += 3)
    mean += 0.2126 * rgb_[i] + 0.7152 * rgb_[i + 1] + 0.0722 * rgb_[i + 2];
  return mean / (static_cast<double>(width_) * height_);
}

TextureImage load_texture_image(const std::string& path, const std::string& what) {
  FloatImage image;
  std::string error;
  if (!image_io().read(path, true, image, error))
    throw InputError(path + ": cannot read " + what + ": " + error);
  const int w = image.width, h = image.height, channels = image.channels;
  if (w < 1 || h < 1 || channels < 1) throw InputError(path + ": empty " + what);
  std::vector<float> rgb(3 * static_cast<std::size_t>(w) * h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < 3; ++c)
        rgb[3 * (static_cast<std::size_t>(y) * w + x) + c] =
            std::max(0.0f, image.at(x, y, std::min(c, channels - 1)));
  return TextureImage(w, h, std::move(rgb));
}

}  // namespace landsim::renderer
