#pragma once
// The rendered image and its first-hit AOVs, in linear RGB, row 0 at the top.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/vec3.h"

namespace landsim::renderer {

class Film {
 public:
  Film(int width, int height);

  int width() const { return width_; }
  int height() const { return height_; }
  std::size_t pixel_count() const { return static_cast<std::size_t>(width_) * height_; }

  void set(int x, int y, const Vec3f& rgb, float depth, const Vec3f& normal, std::uint8_t object);
  Vec3f rgb(int x, int y) const;
  // Rec. 709 luminance of a pixel.
  float luminance(int x, int y) const;
  float depth(int x, int y) const { return depth_[index(x, y)]; }
  Vec3f normal(int x, int y) const;
  std::uint8_t object(int x, int y) const { return object_[index(x, y)]; }

  // Interleaved planes, for writers.
  const std::vector<float>& rgb_data() const { return rgb_; }
  const std::vector<float>& depth_data() const { return depth_; }
  const std::vector<float>& normal_data() const { return normal_; }

 private:
  std::size_t index(int x, int y) const {
    return static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) +
           static_cast<std::size_t>(x);
  }

  int width_;
  int height_;
  std::vector<float> rgb_;
  std::vector<float> depth_;
  std::vector<float> normal_;
  std::vector<std::uint8_t> object_;
};

}  // namespace landsim::renderer
