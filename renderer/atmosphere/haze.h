#pragma once
// Exponential height fog (haze): extinction sigma(z) = sigma0 exp(-(z - base) / H) with
// sigma0 = 3.912 / V (Koschmieder: V is the meteorological range at which contrast falls to
// 2%). Optical depth along any ray has a closed form; distances can be drawn in proportion
// to sigma x transmittance for single scattering.
#include <limits>

#include "core/vec3.h"
#include "renderer/scene.h"

namespace landsim::renderer {

class HazeModel {
 public:
  explicit HazeModel(const Haze& haze);

  bool enabled() const { return enabled_; }
  double sigma(double z) const;  // per metre
  // Optical depth from origin along unit `dir` for `t` metres (t may be infinite).
  double optical_depth(const Vec3& origin, const Vec3& dir, double t) const;
  double transmittance(const Vec3& origin, const Vec3& dir, double t) const;
  // A distance in [0, t] drawn with density sigma(s) T(s) / (1 - T(t)), from u in [0, 1).
  double sample_distance(const Vec3& origin, const Vec3& dir, double t, double u) const;
  // The same with the segment's optical depth (optical_depth(origin, dir, t)) already known.
  double sample_distance(const Vec3& origin, const Vec3& dir, double t, double u,
                         double depth) const;
  // Henyey-Greenstein phase function, per steradian.
  double phase(double cos_theta) const;
  const Vec3f& albedo() const { return albedo_; }

 private:
  bool enabled_;
  double sigma0_, scale_height_, base_, g_;
  Vec3f albedo_;
};

inline constexpr double kInfiniteDistance = std::numeric_limits<double>::infinity();

}  // namespace landsim::renderer
