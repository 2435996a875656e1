#include "renderer/bark_texture.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <cmath>

#include "core/input_error.h"

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
  OIIO::ImageBuf image(path);
  if (!image.read(0, 0, true, OIIO::TypeDesc::FLOAT))
    throw InputError(path + ": cannot read bark texture: " + image.geterror());
  // 8-bit images are sRGB-encoded; float images (EXR) are taken as linear already.
  const bool encoded = image.spec().format.basetype != OIIO::TypeDesc::FLOAT &&
                       image.spec().format.basetype != OIIO::TypeDesc::HALF;
  OIIO::ImageBuf linear =
      encoded ? OIIO::ImageBufAlgo::colorconvert(image, "sRGB", "linear") : image;
  const int w = linear.spec().width, h = linear.spec().height, channels = linear.spec().nchannels;
  if (w < 1 || h < 1) throw InputError(path + ": empty bark texture");
  std::vector<float> rgb(3 * static_cast<std::size_t>(w) * h);
  std::vector<float> px(static_cast<std::size_t>(channels));
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      linear.getpixel(x, y, px.data(), channels);
      for (int c = 0; c < 3; ++c)
        rgb[3 * (static_cast<std::size_t>(y) * w + x) + c] =
            px[static_cast<std::size_t>(std::min(c, channels - 1))];
    }
  }
  return std::make_shared<const BarkTexture>(w, h, std::move(rgb));
}

}  // namespace landsim::renderer
