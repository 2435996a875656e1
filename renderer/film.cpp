#include "renderer/film.h"

namespace landsim::renderer {

Film::Film(int width, int height)
    : width_(width),
      height_(height),
      rgb_(3 * pixel_count()),
      depth_(pixel_count()),
      normal_(3 * pixel_count()),
      object_(pixel_count()) {}

void Film::set(int x, int y, const Vec3f& rgb, float depth, const Vec3f& normal,
               std::uint8_t object) {
  const std::size_t i = index(x, y);
  rgb_[3 * i] = rgb.x;
  rgb_[3 * i + 1] = rgb.y;
  rgb_[3 * i + 2] = rgb.z;
  depth_[i] = depth;
  normal_[3 * i] = normal.x;
  normal_[3 * i + 1] = normal.y;
  normal_[3 * i + 2] = normal.z;
  object_[i] = object;
}

Vec3f Film::rgb(int x, int y) const {
  const std::size_t i = 3 * index(x, y);
  return {rgb_[i], rgb_[i + 1], rgb_[i + 2]};
}

float Film::luminance(int x, int y) const {
  const Vec3f c = rgb(x, y);
  return 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z;
}

Vec3f Film::normal(int x, int y) const {
  const std::size_t i = 3 * index(x, y);
  return {normal_[i], normal_[i + 1], normal_[i + 2]};
}

}  // namespace landsim::renderer
