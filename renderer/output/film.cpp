#include "renderer/output/film.h"

#include <algorithm>
#include <utility>

namespace landsim::renderer {

Film::Film(int width, int height, std::vector<std::string> band_names)
    : width_(width),
      height_(height),
      rgb_(3 * pixel_count()),
      depth_(pixel_count()),
      normal_(3 * pixel_count()),
      albedo_(3 * pixel_count()),
      object_(pixel_count()),
      species_(pixel_count(), kNoId),
      instance_(pixel_count(), kNoId),
      level_(pixel_count()),
      target_(pixel_count()),
      samples_(pixel_count()),
      coverage_(pixel_count()),
      position_(3 * pixel_count(), kNoPosition),
      variance_(pixel_count()),
      band_names_(std::move(band_names)),
      bands_(band_names_.size(), std::vector<float>(pixel_count())) {}

bool Film::order_bands(const std::vector<std::string>& names) {
  if (names.size() != band_names_.size()) return false;
  std::vector<std::vector<float>> ordered;
  for (const std::string& name : names) {
    const auto it = std::find(band_names_.begin(), band_names_.end(), name);
    if (it == band_names_.end()) return false;
    ordered.push_back(bands_[static_cast<std::size_t>(it - band_names_.begin())]);
  }
  bands_ = std::move(ordered);
  band_names_ = names;
  return true;
}

void Film::add_band(std::string name, std::vector<float> plane) {
  plane.resize(pixel_count());
  band_names_.push_back(std::move(name));
  bands_.push_back(std::move(plane));
}

void Film::set_bands(int x, int y, const float* bands) {
  const std::size_t i = index(x, y);
  for (auto& plane : bands_) plane[i] = *bands++;
}

void Film::set(int x, int y, const Vec3f& rgb, const PixelAovs& a) {
  const std::size_t i = index(x, y);
  for (int c = 0; c < 3; ++c) {
    rgb_[3 * i + c] = rgb[c];
    normal_[3 * i + c] = a.normal[c];
    albedo_[3 * i + c] = a.albedo[c];
    position_[3 * i + c] = a.position[c];
  }
  depth_[i] = a.depth;
  object_[i] = a.object;
  species_[i] = a.species;
  instance_[i] = a.instance;
  level_[i] = a.level;
  target_[i] = a.target;
  coverage_[i] = a.coverage;
}

Vec3f Film::triple(const std::vector<float>& plane, int x, int y) const {
  const std::size_t i = 3 * index(x, y);
  return {plane[i], plane[i + 1], plane[i + 2]};
}

Vec3f Film::position(int x, int y) const { return triple(position_, x, y); }

Vec3f Film::rgb(int x, int y) const { return triple(rgb_, x, y); }

float Film::luminance(int x, int y) const {
  const Vec3f c = rgb(x, y);
  return 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z;
}

Vec3f Film::normal(int x, int y) const { return triple(normal_, x, y); }

Vec3f Film::albedo(int x, int y) const { return triple(albedo_, x, y); }

}  // namespace landsim::renderer
