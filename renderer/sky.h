#pragma once
// Radiance arriving from a direction that leaves the scene (the sun disc excluded: the sun
// is reached by next-event estimation only), with an importance-sampling table over the
// sphere for next-event estimation of the sky.
#include <array>
#include <memory>
#include <vector>

#include "core/vec3.h"
#include "renderer/scene.h"

namespace landsim::renderer {

class PreethamSky;

class SkyModel {
 public:
  SkyModel(const Sky& sky, const Sun& sun, Vec3f ground_albedo);
  ~SkyModel();
  SkyModel(SkyModel&&) noexcept;

  // Sky radiance above the horizon. Below it, where a ray leaves a finite terrain, the
  // radiance of an endless sunlit plain of the ground albedo, so the edge of a DEM does not
  // open onto a black void.
  Vec3f radiance(const Vec3f& direction) const;
  // Irradiance the sky alone gives a horizontal surface.
  Vec3f horizontal_irradiance() const { return sky_irradiance_; }
  // Radiance averaged over the whole sphere (sky above, the sunlit plain below): what haze
  // scatters toward the viewer from skylight, taken as isotropic.
  Vec3f mean_radiance() const { return mean_radiance_; }

  // A direction drawn in proportion to luminance x solid angle; `pdf` per steradian.
  Vec3f sample(float u1, float u2, float& pdf) const;
  float pdf(const Vec3f& direction) const;

 private:
  Vec3f above_horizon(const Vec3f& direction) const;
  void build_table();

  Sky sky_;
  std::unique_ptr<PreethamSky> preetham_;
  Vec3f sky_irradiance_;
  Vec3f below_horizon_;
  Vec3f mean_radiance_;
  // Sampling table: rows of theta (0 = zenith), columns of phi.
  std::vector<float> weights_;   // per cell
  std::vector<float> row_cdf_;   // kRows + 1
  std::vector<float> cell_cdf_;  // per row, kCols + 1
  float total_ = 0.0f;
};

// Sun irradiance on a surface facing it, linear RGB in the renderer's unit, after Rayleigh
// and aerosol extinction (Angstrom turbidity from Preetham's relation, Kasten-Young air mass).
Vec3f sun_irradiance(double elevation_deg, double turbidity);

}  // namespace landsim::renderer
