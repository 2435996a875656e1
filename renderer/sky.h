#pragma once
// Radiance arriving from a direction that leaves the scene.
#include "core/vec3.h"
#include "renderer/scene.h"

namespace landsim::renderer {

class SkyModel {
 public:
  SkyModel(const Sky& sky, const Sun& sun, Vec3f ground_albedo);

  // Sky radiance above the horizon. Below it, where a ray leaves a finite terrain, the
  // radiance of an endless sunlit plain of the ground albedo, so the edge of a DEM does not
  // open onto a black void.
  Vec3f radiance(const Vec3f& direction) const;
  // Irradiance the sky alone gives a horizontal surface (for tests and the plain below).
  Vec3f horizontal_irradiance() const { return sky_irradiance_; }

 private:
  Vec3f above_horizon(float cos_zenith) const;

  Sky sky_;
  Vec3f sky_irradiance_;
  Vec3f below_horizon_;
};

}  // namespace landsim::renderer
