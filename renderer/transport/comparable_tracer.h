#pragma once
// The POV-comparable integrator (the cross-check, docs/CROSSCHECK.md): what POV-Ray's scene
// export computes, so that a difference between the two images is a renderer difference.
// The camera ray's first hit only: sunlight with its shadow ray (not dimmed by haze, as
// POV-Ray's fog does not dim light sources), an unoccluded ambient light (albedo x
// irradiance / pi, POV-Ray's ambient_light), opaque leaves and grass, and haze as uniform
// fog of one colour at the base height's density (POV-Ray's fog_type 1); the sky where
// nothing is hit. It draws the same sun sample as PathTracer's first bounce.
#include <cstdint>

#include "renderer/acceleration/embree_scene.h"
#include "renderer/atmosphere/medium.h"
#include "renderer/atmosphere/sky.h"
#include "renderer/transport/integrator.h"

namespace landsim::renderer {

struct ComparableLight {
  Vec3f ambient_irradiance;  // on a horizontal surface from the whole sky
  Vec3f fog_colour;
};

class ComparableTracer : public Integrator {
 public:
  ComparableTracer(const Scene& scene, const EmbreeScene& embree, ComparableLight light);

  PathSample trace(const Ray& camera_ray, const CounterRng& rng,
                   std::uint32_t mask = kAllBuckets) const override;

 private:
  const Scene& scene_;
  const EmbreeScene& embree_;
  ComparableLight light_;
  SkyModel sky_;
  double fog_extinction_;  // per metre, uniform: the haze base's (0 without haze)
  Vec3f sun_direction_;
};

}  // namespace landsim::renderer
