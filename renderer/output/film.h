#pragma once
// The rendered image and its first-hit AOVs (ground truth for detection studies), linear
// RGB, row 0 at the top.
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "core/vec3.h"

namespace landsim::renderer {

inline constexpr std::uint32_t kNoId = 0xffffffffu;
inline constexpr float kNoPosition = std::numeric_limits<float>::quiet_NaN();

// What the first hit of a pixel's first sample saw, and (target, coverage) what all of its
// samples saw of the scene objects.
struct PixelAovs {
  float depth = 0.0f;              // distance from the camera, metres; infinity for the sky
  Vec3f normal;                    // shading normal facing the camera; zero for the sky
  Vec3f albedo;                    // reflectance + transmittance
  std::uint32_t object = 0;        // ObjectClass
  std::uint32_t species = kNoId;   // species index, trees only
  std::uint32_t instance = kNoId;  // tree instance index
  std::uint32_t level = 0;         // level of detail drawn (0 = full)
  // The scene object (index + 1) most of the pixel's samples first hit (0: none hit one) and
  // the fraction of the samples that hit it: sub-pixel truth (docs/OBJECTS.md "Truth").
  std::uint32_t target = 0;
  float coverage = 0.0f;
  // Where the first sample's ray first hits, scene frame (the scene's origin added gives the
  // terrain's CRS); NaN where it hits nothing.
  Vec3f position{kNoPosition, kNoPosition, kNoPosition};
};

class Film {
 public:
  // `band_names`: the sensor bands (renderer/scene.h SpectralBand) the film also holds, one
  // plane each, in band radiance (W m^-2 sr^-1); a name with a '.' is a layer of its own
  // ("photons.<channel>", "reflectance.<band>": image_output.h band_layer).
  Film(int width, int height, std::vector<std::string> band_names = {});

  int width() const { return width_; }
  int height() const { return height_; }
  std::size_t pixel_count() const { return static_cast<std::size_t>(width_) * height_; }

  void set(int x, int y, const Vec3f& rgb, const PixelAovs& aovs);
  // The pixel's band radiances, band_count() of them.
  void set_bands(int x, int y, const float* bands);
  // Another plane, `plane` holding pixel_count() values (derived layers: reflectance).
  void add_band(std::string name, std::vector<float> plane);
  int band_count() const { return static_cast<int>(band_names_.size()); }
  const std::string& band_name(int b) const { return band_names_[static_cast<std::size_t>(b)]; }
  const std::vector<std::string>& band_names() const { return band_names_; }
  float band(int x, int y, int b) const { return bands_[static_cast<std::size_t>(b)][index(x, y)]; }
  // Puts the band planes in the order of `names` (EXR files list channels alphabetically);
  // false, and nothing changed, unless the film holds exactly those bands.
  bool order_bands(const std::vector<std::string>& names);
  std::vector<float>& band_data(int b) { return bands_[static_cast<std::size_t>(b)]; }
  const std::vector<float>& band_data(int b) const { return bands_[static_cast<std::size_t>(b)]; }
  Vec3f rgb(int x, int y) const;
  float luminance(int x, int y) const;  // Rec. 709
  float depth(int x, int y) const { return depth_[index(x, y)]; }
  Vec3f normal(int x, int y) const;
  Vec3f albedo(int x, int y) const;
  std::uint8_t object(int x, int y) const {
    return static_cast<std::uint8_t>(object_[index(x, y)]);
  }
  std::uint32_t species(int x, int y) const { return species_[index(x, y)]; }
  std::uint32_t instance(int x, int y) const { return instance_[index(x, y)]; }
  std::uint32_t level(int x, int y) const { return level_[index(x, y)]; }
  std::uint32_t target(int x, int y) const { return target_[index(x, y)]; }
  // The variance of the pixel's luminance estimate (the sample variance of its samples'
  // luminance over the sample count), (cd/m2)^2: its standard error squared, for telling a
  // difference from Monte Carlo noise (docs/SENSOR.md "Noise of the render").
  float luminance_variance(int x, int y) const { return variance_[index(x, y)]; }
  void set_luminance_variance(int x, int y, float v) { variance_[index(x, y)] = v; }
  // The samples the pixel took (every pixel the same but under adaptive sampling).
  std::uint32_t samples(int x, int y) const { return samples_[index(x, y)]; }
  void set_samples(int x, int y, std::uint32_t n) { samples_[index(x, y)] = n; }
  float coverage(int x, int y) const { return coverage_[index(x, y)]; }
  Vec3f position(int x, int y) const;

  // Planes, for writers and readers (checkpoints).
  std::vector<float>& rgb_data() { return rgb_; }
  const std::vector<float>& rgb_data() const { return rgb_; }
  std::vector<float>& depth_data() { return depth_; }
  const std::vector<float>& depth_data() const { return depth_; }
  std::vector<float>& normal_data() { return normal_; }
  const std::vector<float>& normal_data() const { return normal_; }
  std::vector<float>& albedo_data() { return albedo_; }
  const std::vector<float>& albedo_data() const { return albedo_; }
  std::vector<std::uint32_t>& object_data() { return object_; }
  const std::vector<std::uint32_t>& object_data() const { return object_; }
  std::vector<std::uint32_t>& species_data() { return species_; }
  const std::vector<std::uint32_t>& species_data() const { return species_; }
  std::vector<std::uint32_t>& instance_data() { return instance_; }
  const std::vector<std::uint32_t>& instance_data() const { return instance_; }
  std::vector<std::uint32_t>& level_data() { return level_; }
  const std::vector<std::uint32_t>& level_data() const { return level_; }
  std::vector<std::uint32_t>& target_data() { return target_; }
  const std::vector<std::uint32_t>& target_data() const { return target_; }
  std::vector<float>& position_data() { return position_; }
  const std::vector<float>& position_data() const { return position_; }
  std::vector<float>& coverage_data() { return coverage_; }
  std::vector<float>& variance_data() { return variance_; }
  const std::vector<float>& variance_data() const { return variance_; }
  std::vector<std::uint32_t>& samples_data() { return samples_; }
  const std::vector<std::uint32_t>& samples_data() const { return samples_; }
  const std::vector<float>& coverage_data() const { return coverage_; }

 private:
  // Pixel (x, y) of an interleaved three-value plane (rgb, normal, albedo, position).
  Vec3f triple(const std::vector<float>& plane, int x, int y) const;
  std::size_t index(int x, int y) const {
    return static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) +
           static_cast<std::size_t>(x);
  }

  int width_;
  int height_;
  std::vector<float> rgb_, depth_, normal_, albedo_;
  std::vector<std::uint32_t> object_, species_, instance_, level_, target_, samples_;
  std::vector<float> coverage_, position_, variance_;
  std::vector<std::string> band_names_;
  std::vector<std::vector<float>> bands_;  // per band, a plane
};

}  // namespace landsim::renderer
