#pragma once
// The plane-parallel scenes of the radiative-transfer checks: a homogeneous layer over an
// endless flat Lambertian ground, lit by a collimated sun and an isotropic sky from above
// (either may be zero), and the path tracer's estimates of what DISORT reports there:
// radiance leaving the top in a direction, and irradiance through a horizontal plane.
#include <cmath>
#include <memory>
#include <numbers>

#include "core/counter_rng.h"
#include "renderer/acceleration/embree_scene.h"
#include "renderer/scene.h"
#include "renderer/transport/path_tracer.h"

namespace landsim::renderer::testing {

struct LayerSetup {
  double optical_depth = 1.0;
  double albedo = 1.0;  // single scattering
  AerosolPhase phase = AerosolPhase::isotropic;
  double asymmetry = 0.0;
  double beam = 0.0;       // the sun's irradiance across its beam (DISORT's FBEAM)
  double mu0 = 1.0;        // cosine of the sun's zenith angle; the sun stands in -x
  double isotropic = 0.0;  // the sky's radiance from every downward direction (FISOT)
  double ground = 0.0;     // Lambertian albedo
  double top = 1000.0;     // metres: the layer's thickness
  // Every scattering event traced (the checks' default), or the tabulated haze light.
  HazeScattering scattering = HazeScattering::paths;
};

// A Monte Carlo estimate and its standard error.
struct Estimate {
  double mean = 0.0, error = 0.0;
};

class PlaneParallel {
 public:
  // Radiances are reported in the units of `beam` (or of `isotropic` when there is no beam),
  // at the bin near 550 nm; the layer is grey, so every bin is alike.
  explicit PlaneParallel(const LayerSetup& l) : setup_(l) {
    constexpr float kLux = 10000.0f;  // the scene's sun; any scale, divided out below
    const double reference = l.beam > 0.0 ? l.beam : l.isotropic;
    scale_ = reference / kLux;
    const auto sky = static_cast<float>(l.isotropic / reference * kLux);
    scene_.sky.model = SkyKind::gradient;
    scene_.sky.zenith_radiance = scene_.sky.horizon_radiance = {sky, sky, sky};
    scene_.sun.direction = {-std::sqrt(1.0 - l.mu0 * l.mu0), 0.0, l.mu0};
    const float sun = l.beam > 0.0 ? kLux : 0.0f;
    scene_.sun.irradiance = {sun, sun, sun};
    scene_.sun.angular_radius = 1e-6;
    const auto a = static_cast<float>(l.ground);
    scene_.ground.albedo = {a, a, a};
    scene_.ground.edge_albedo = Vec3f{a, a, a};
    scene_.ground.plain_height = 0.0f;
    scene_.ground.mesh.vertices = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
    scene_.ground.mesh.normals.assign(4, Vec3f{0.0f, 0.0f, 1.0f});
    scene_.ground.mesh.indices = {0, 1, 2, 0, 2, 3};
    scene_.haze.enabled = true;
    scene_.haze.scattering = l.scattering;
    scene_.haze.layer = HazeLayer{l.optical_depth, l.top};
    scene_.haze.base_height = 0.0;
    scene_.haze.albedo = Vec3f{static_cast<float>(l.albedo), static_cast<float>(l.albedo),
                               static_cast<float>(l.albedo)};
    scene_.haze.phase = l.phase;
    scene_.haze.asymmetry = l.asymmetry;
    embree_ = std::make_unique<EmbreeScene>(scene_);
    tracer_ = std::make_unique<PathTracer>(scene_, *embree_);
    // The scene's sun or sky in that bin, as `reference`.
    unit_ = l.beam > 0.0 ? tracer_->sky().sun_spectral_irradiance()[kBin] / kLux
                         : tracer_->sky().spectral_radiance({0.0f, 0.0f, 1.0f})[kBin] /
                               static_cast<float>(sky);
  }

  const PathTracer& tracer() const { return *tracer_; }
  Scene& scene() { return scene_; }

  // DISORT's intensity at the top travelling up at polar cosine mu and azimuth phi (degrees,
  // 0: away from the sun).
  Estimate top_intensity(double mu, double phi_deg, int paths) const {
    const double phi = phi_deg * std::numbers::pi / 180.0, s = std::sqrt(1.0 - mu * mu);
    const Vec3f up(Vec3{s * std::cos(phi), s * std::sin(phi), mu});
    return estimate(paths, 11, [&](const CounterRng&) {
      return Ray{{0.0f, 0.0f, static_cast<float>(setup_.top + 1.0)}, -up};
    });
  }
  // Diffuse irradiance through a horizontal plane at height z: downward (rays looking up) or
  // upward (rays looking down), the sun's beam left out.
  Estimate flux(double z, bool downward, int paths) const {
    const Estimate e = estimate(paths, 12, [&](const CounterRng& rng) {
      const std::array<float, 2> u = rng.uniform2(0);
      const float r = std::sqrt(u[0]), a = 2.0f * std::numbers::pi_v<float> * u[1];
      const float c = std::sqrt(std::max(0.0f, 1.0f - u[0]));
      return Ray{{0.0f, 0.0f, static_cast<float>(z)},
                 {r * std::cos(a), r * std::sin(a), downward ? c : -c}};
    });
    return {e.mean * std::numbers::pi, e.error * std::numbers::pi};
  }

 private:
  static constexpr int kBin = 9;  // 560-580 nm

  template <class MakeRay>
  Estimate estimate(int paths, std::uint64_t key, MakeRay make_ray) const {
    double sum = 0.0, sum2 = 0.0;
    for (int i = 0; i < paths; ++i) {
      const CounterRng rng(77, key, static_cast<std::uint64_t>(i), SampleSequence::sobol);
      PathSample sample;
      const double l =
          tracer_->radiance(make_ray(rng), rng, kAllBuckets, false, sample)[kBin] / unit_ * scale_;
      sum += l;
      sum2 += l * l;
    }
    const double mean = sum / paths;
    const double var = std::max(0.0, sum2 / paths - mean * mean);
    return {mean, std::sqrt(var / paths)};
  }

  LayerSetup setup_;
  Scene scene_;
  std::unique_ptr<EmbreeScene> embree_;
  std::unique_ptr<PathTracer> tracer_;
  double scale_ = 1.0;
  double unit_ = 1.0;
};

}  // namespace landsim::renderer::testing
