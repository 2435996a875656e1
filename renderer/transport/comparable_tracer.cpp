#include "renderer/transport/comparable_tracer.h"

#include <array>
#include <cmath>
#include <limits>
#include <numbers>

#include "renderer/transport/detail/sample_dimensions.h"
#include "renderer/transport/surface.h"

namespace landsim::renderer {
namespace {

constexpr float kPi = std::numbers::pi_v<float>;
constexpr float kInfinity = std::numeric_limits<float>::infinity();

}  // namespace

ComparableTracer::ComparableTracer(const Scene& scene, const EmbreeScene& embree,
                                   ComparableLight light)
    : scene_(scene),
      embree_(embree),
      light_(light),
      sky_(scene.sky, scene.sun, scene.ground.plain_albedo(), scene.spectral_grid),
      fog_extinction_(visibility_extinction(scene.haze)),
      sun_direction_(Vec3f(normalize(scene.sun.direction))) {}

PathSample ComparableTracer::trace(const Ray& ray, const CounterRng& rng,
                                   std::uint32_t mask) const {
  using namespace detail;
  PathSample out;
  out.first.depth = kInfinity;
  Vec3f throughput{1.0f, 1.0f, 1.0f};
  ++out.rays;
  const auto hit = embree_.intersect(ray, 0.0f, kInfinity, mask);
  if (hit || ray.direction.z <= 0.0f) {
    // Uniform fog of the base height's density over the segment, of one colour.
    const double t = hit ? hit->t : kInfiniteDistance;
    const auto transmitted =
        static_cast<float>(fog_extinction_ > 0.0 ? std::exp(-fog_extinction_ * t) : 1.0);
    out.radiance += throughput * light_.fog_colour * (1.0f - transmitted);
    throughput = throughput * transmitted;
  }
  if (!hit) {
    out.radiance += throughput * sky_.radiance(ray.direction);
    return out;
  }
  const ShadingPoint v = shading_point(ray, *hit, mask);
  SurfaceMaterial m = surface_material(scene_, *hit, v);
  m.transmittance = {};  // POV-Ray's leaves are opaque
  out.first = first_hit(scene_, *hit, v, m);
  const float fresnel = Bsdf(m, v.frame()).fresnel(ray.direction);
  const std::uint32_t dim = kFirstBounceDim;
  const std::array<float, 2> sun = rng.uniform2(dim + kSun0);
  Vec3f direct = sample_sun(scene_, embree_, sun_direction_, v, m, sun[0], sun[1], out.rays).light;
  direct += m.reflectance * light_.ambient_irradiance * (1.0f / kPi);
  out.radiance += throughput * direct * (1.0f - fresnel);
  return out;
}

}  // namespace landsim::renderer
