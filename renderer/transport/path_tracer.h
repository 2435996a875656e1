#pragma once
// Unidirectional spectral path tracer, the physical integrator: every path carries the 32
// wavelength bins of renderer/spectra/spectrum.h, its RGB comes from them through the CIE functions
// (docs/SPECTRAL.md); Lambertian and two-sided (leaf, grass) surfaces, a Fresnel water mirror;
// the haze as a participating medium (renderer/atmosphere/medium.h: scattering points on every
// segment it touches, renderer/transport/medium_segment.h); next-event estimation of the sun
// disc and the sky from surfaces and haze points alike (the sky importance-sampled and combined
// with the BSDF's or phase function's own sampling by multiple importance sampling; at an open
// first vertex, through a closed-form control variate, renderer/atmosphere/sky_irradiance.h).
// Paths end by Russian roulette on their spectral throughput alone (docs/ATMOSPHERE.md
// "Paths"); shadow rays after the first vertex are rouletted by their contribution
// (renderer/transport/shadow_roulette.h).
#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "core/counter_rng.h"
#include "renderer/acceleration/embree_scene.h"
#include "renderer/atmosphere/direction_table.h"
#include "renderer/atmosphere/medium.h"
#include "renderer/atmosphere/sky.h"
#include "renderer/atmosphere/sky_irradiance.h"
#include "renderer/camera.h"
#include "renderer/guiding/guiding_field.h"
#include "renderer/output/atmosphere_layers.h"
#include "renderer/transport/integrator.h"
#include "renderer/transport/medium_segment.h"
#include "renderer/transport/plain.h"
#include "renderer/transport/surface.h"

namespace landsim::renderer {

class ScatteringTable;
class RadianceModel;

// A path's longest run of scattering events when the scene sets no limit: a guard against
// a path that never ends, not a bias (docs/ATMOSPHERE.md "Paths": no measured band moves by
// 0.1% between it and a quarter of it).
inline constexpr int kSafetyBounces = 100000;

class PathTracer : public Integrator {
 public:
  // `table`: the scene's haze table when one is at hand (a renderer shares one among its
  // views); built here when the scene asks for one and none is given.
  // `table`, `model`: built already for the scene (shared by its views); null: built here
  // when the scene wants them.
  PathTracer(const Scene& scene, const EmbreeScene& embree,
             std::shared_ptr<const ScatteringTable> table = nullptr,
             std::shared_ptr<const RadianceModel> model = nullptr);
  // Whether `scene` takes its haze's further light from a table (HazeScattering::table).
  static bool wants_table(const Scene& scene);
  // Whether `scene`'s paths take the one atmosphere's higher orders through the radiance
  // model's control variate (renderer/transport/radiance_model.h).
  static bool wants_radiance_model(const Scene& scene);

  PathSample trace(const Ray& camera_ray, const CounterRng& rng,
                   std::uint32_t mask = kAllBuckets) const override;
  // The spectral radiance arriving along -ray.direction at ray.origin. `sun_disc`: whether a
  // ray that meets the sun's disc sees it (false: diffuse light alone, as irradiance
  // meters split it). `sky_single_scattering` false: without the sun's single scattering on
  // the ray's own segment where it leaves into the sky (what the one atmosphere's haze points
  // take by next-event estimation; renderer/transport/radiance_model.h models the rest).
  // `parts`: the atmosphere's parts of the camera ray's light (renderer/output/
  // atmosphere_layers.h), filled when given.
  Spectrum radiance(const Ray& ray, const CounterRng& rng, std::uint32_t mask, bool sun_disc,
                    PathSample& out, bool sky_single_scattering = true,
                    AtmosphereSample* parts = nullptr) const;

  // Guided paths (renderer/guiding/guiding_field.h; docs/PERFORMANCE.md "Guided paths"): with
  // a field, a diffuse surface vertex draws its next direction from the field's directional
  // tree there or from its BSDF (kBsdfShare of the time), weighed by the mixture's density.
  // Null: the BSDF alone. Set between passes, never while paths are traced.
  void guide_by(std::shared_ptr<const GuidingField> field) { guide_ = std::move(field); }
  // The share of guided vertices that sample their BSDF. The paper's fixed 0.5 gave more noise
  // than 0.7 on every scene measured (docs/PERFORMANCE.md "Guided paths").
  static constexpr float kBsdfShare = 0.7f;
  // A training sample: trace() that also appends, for every diffuse surface vertex of its
  // paths, what came back along the direction it left in (renderer/guiding/guiding_field.h).
  PathSample train(const Ray& camera_ray, const CounterRng& rng, std::uint32_t mask,
                   std::vector<GuideRecord>& records) const;

  const SkyModel& sky() const { return sky_; }
  const Medium& medium() const { return medium_; }

 private:
  // A path between vertices: where it goes, what it carries, and the dimensions of its
  // random numbers (a branch takes its own, far from the camera path's).
  struct PathState {
    Ray ray;
    Spectrum throughput;
    float last_pdf = 0.0f;
    bool last_specular = true;
    // How the one atmosphere's single-scattered sky that this ray meets where it leaves into
    // the sky counts: whole (no vertex took it), weighed against the surface's next-event
    // estimation that took it too (multiple importance sampling), or not at all (a haze point
    // took all of it: haze_atmosphere_sky).
    enum class SkyTaken : std::uint8_t { no, shared, whole };
    SkyTaken sky_taken = SkyTaken::no;
    int bounce = 0;
    std::uint32_t dimension_offset = 0;
    // Training: where the path's vertices' records go (null: not recorded).
    std::vector<GuideRecord>* records = nullptr;
  };
  // A training path's surface vertices, up to kTrailLength: where each left from, in which
  // direction with which density, the throughput after it and the radiance the path had
  // gathered by then (what came back along its direction is the rest, over that throughput).
  struct TrailVertex {
    Vec3f position, direction;
    float pdf = 0.0f;
    Spectrum throughput, gathered;
    Spectrum unweighted_sky;  // the sky its own ray met, less the share MIS gave it
  };
  static constexpr int kTrailLength = 16;
  // A camera ray's path state; `sky_single_scattering` as radiance()'s.
  static PathState camera_state(const Ray& camera_ray, bool sky_single_scattering);
  // The camera path and its branch from the haze: radiance()'s work.
  Spectrum gather(const PathState& camera, const CounterRng& rng, std::uint32_t mask, bool sun_disc,
                  PathSample& out, AtmosphereSample* parts) const;
  struct Trail {
    std::array<TrailVertex, kTrailLength> vertex;
    int length = 0;
  };
  // The sun's shadow ray at a surface vertex, as sun_light traced it: its direction, whether
  // it was traced from the side the vertex was seen from (`front`), whether it found the sun,
  // and the air's transmittance to it there.
  struct SunRay {
    Vec3f l;
    bool traced = false, front = false, open = false;
    Spectrum transmittance;
  };
  static constexpr std::uint32_t kBranchDimensions = 1u << 30;
  // The first vertex's path for the diffuse irradiance (atmosphere layers): above a branch's
  // dimensions and its haze points' (kBranchDimensions + kHazeSkyOffset).
  static constexpr std::uint32_t kIrradianceDimensions = 1u << 31;
  // Follows `path` to its end, adding what it sees to `radiance`; its camera segment may
  // leave a branch from the haze (`branch` null: none). `parts`: the camera path's light
  // before its first vertex (path radiance), the camera segment's transmittance, and the
  // irradiance at the first vertex.
  void follow(PathState path, const CounterRng& rng, std::uint32_t mask, bool sun_disc,
              PathSample& out, Spectrum& radiance, std::optional<PathState>* branch,
              AtmosphereSample* parts = nullptr) const;
  // follow's loop; `trail` (training) gathers the surface vertices.
  void follow_path(PathState path, const CounterRng& rng, std::uint32_t mask, bool sun_disc,
                   PathSample& out, Spectrum& radiance, std::optional<PathState>* branch,
                   AtmosphereSample* parts, Trail* trail) const;
  // The trail's records, `radiance` being the path's at its end.
  void record(const Trail& trail, const Spectrum& radiance, std::vector<GuideRecord>& out) const;
  // The directional tree guiding a vertex of material `m` at `p`; null: the BSDF alone
  // (no field, nothing learned there, or a mirror's water).
  const DirectionalTree* guide_at(const SurfaceMaterial& m, const Vec3f& p) const;
  // The density the vertex draws its next direction `l` with: its BSDF's, or the mixture of
  // the BSDF's and the tree's (what the sky's MIS weighs against).
  static float scatter_pdf(const Bsdf& bsdf, const DirectionalTree* tree, const Vec3f& l);
  // The vertex's next direction: Bsdf::sample, or with a tree, the mixture's draw weighed by
  // f cos over the mixture's density (one-sample MIS, Müller et al. 2017 section 4).
  BsdfSample scatter(const Bsdf& bsdf, const DirectionalTree* tree, const SpectralMaterial& s,
                     const Vec3f& incoming, float fresnel, const BsdfNumbers& u,
                     float u_strategy) const;
  // The direct and diffuse irradiance on the side of `v` facing the camera ray `incoming`: the
  // sun along the vertex's own sun ray `sun` (its shadow ray reused where sun_light traced it
  // from that side), the rest by one path from a cosine-distributed direction.
  // Illumination truth at the camera path's first surface (renderer/output/
  // illumination_layers.h), written to out.bands from illumination_plane_: whether the sun's
  // centre lights it, and the share of cosine-distributed directions about its normal that
  // reach the sky.
  void illumination_at(const ShadingPoint& v, const SurfaceMaterial& m, const CounterRng& rng,
                       std::uint32_t mask, PathSample& out) const;
  // Its random numbers: above the diffuse irradiance path's (kIrradianceDimensions + a path).
  static constexpr std::uint32_t kIlluminationDimensions = (1u << 31) + (1u << 30);
  void irradiance_at(const ShadingPoint& v, const Vec3f& incoming, const SunRay& sun,
                     const CounterRng& rng, std::uint32_t mask, PathSample& out,
                     AtmosphereSample& parts) const;
  // Turns `path` at haze point `p` (reached with probability q); false when it ends there.
  bool scatter_from(const MediumPoint& p, float q, const CounterRng& rng, std::uint32_t dim,
                    PathState& path) const;
  // Russian roulette on the spectral throughput after the first bounces; the survivor is
  // divided by its survival probability.
  bool survives(Spectrum& throughput, int bounce, float u) const;
  // The sky's closed-form model at an opaque diffuse vertex
  // (renderer/atmosphere/sky_irradiance.h): its reflectance over pi, the normal facing the
  // viewer and the normal's bin.
  struct SkyControl {
    Spectrum reflect;
    Vec3f n;
    int bin = 0;
  };
  // The control variate's parts: the model's integral (exact) and its integrand toward l.
  Spectrum control_integral(const SkyControl& c) const;
  Spectrum control_integrand(const SkyControl& c, const Vec3f& l) const;
  // Light at a surface vertex, as the path's `throughput` so far will see it (the throughput
  // decides the shadow ray's roulette `r`; it is not applied to the result).
  Spectrum sun_light(const ShadingPoint& v, const Bsdf& bsdf, const SpectralMaterial& s, float u1,
                     float u2, const Spectrum& throughput, const ShadowRoulette& r,
                     std::uint32_t& rays, SunRay& ray) const;
  // With `control`, the sky's estimate less the model's integrand there (its integral is
  // added at the vertex), and no roulette: an unoccluded ray then adds almost nothing.
  // Under the one atmosphere, `point` (bin, distance, the sun's two) draws the scattering
  // point on the sky ray and its sun direction: the sky's radiance there is estimated, not
  // looked up (docs/ATMOSPHERE.md "Sampling the atmosphere's sky").
  struct SkyPoint {
    std::array<float, 2> position, sun;
    std::uint32_t mask = 0;
  };
  Spectrum sky_light(const ShadingPoint& v, const Bsdf& bsdf, const SpectralMaterial& s, float u1,
                     float u2, const Spectrum& throughput, const ShadowRoulette& r,
                     const SkyControl* control, const SkyPoint* point, const DirectionalTree* tree,
                     std::uint32_t& rays) const;
  // The one atmosphere's single scattering along the sky ray from `origin` toward `l`: one
  // point drawn on it, the sun by a shadow ray from there.
  Spectrum atmosphere_sky(const Vec3f& origin, const Vec3f& l, const SkyPoint& point,
                          std::uint32_t& rays) const;
  // Light scattered at haze point `p` along the path's direction `d` (the sun and sky by
  // next-event estimation); `trace_sun`: the sun's shadow ray is not rouletted.
  // `sky_nee`: under the one atmosphere, the sky's single scattering by next-event estimation
  // too (a scattering event more: not at the path's last allowed bounce).
  // `sun_weight` multiplies the sun's single scattering alone (the MIS weight of a ray into
  // the atmosphere's sky that a surface or haze point also took by next-event estimation).
  Spectrum haze_light(const MediumPoint& p, const Vec3f& d, const Spectrum& throughput,
                      const CounterRng& rng, std::uint32_t dim, bool trace_sun, bool sky_nee,
                      float sun_weight, std::uint32_t mask, std::uint32_t& rays) const;
  // The one atmosphere's sky at haze point `p` by next-event estimation, all of it: the
  // direction from a mixture of the sky's table and the phase function (a path goes on from a
  // haze point only now and then, and would carry a share of it with a weight of 1 / q).
  Spectrum haze_atmosphere_sky(const MediumPoint& p, const Vec3f& d, const CounterRng& rng,
                               std::uint32_t dim, std::uint32_t mask, std::uint32_t& rays) const;
  // The scene's geometry and, past it, the plain beyond the grid (renderer/transport/plain.h);
  // or, in a periodic cell, its endless repetition: `ray` then becomes the leg that hit.
  // `travelled`: as periodic_intersect's (0 outside a periodic cell).
  std::optional<Hit> intersect(Ray& ray, std::uint32_t mask, double* travelled = nullptr) const;
  bool occluded(const Ray& ray, std::uint32_t mask) const;
  // The sky seen from `origin` along `l` through the haze: its radiance transmitted and, with
  // the scattering table, the haze's own light along the way.
  Spectrum hazy_sky(const Vec3f& origin, const Vec3f& l) const;
  // Everything a surface at `origin` receives from the sky along `l`: hazy_sky and, with the
  // hazy sky's table, the haze's aureole about the sun. One light, sampled as one: a single
  // shadow ray per vertex for the sky, the haze's light and the aureole together.
  Spectrum surface_sky(const Vec3f& origin, const Vec3f& l) const;
  // A direction for that light's next-event estimation, and its density: in proportion to
  // the hazy sky's luminance seen from the plain's height (hazy_table_), else the sky's.
  Vec3f sample_sky(float u1, float u2, float& pdf) const;
  float sky_pdf(const Vec3f& l) const;
  // Transmittance from `origin` along `l` into the sky.
  Spectrum to_sky(const Vec3f& origin, const Vec3f& l) const;
  ShadowRoulette roulette(float u) const { return {roulette_threshold_, u}; }
  // What the roulettes weigh a spectrum by: its largest bin among those an output sees (the
  // near infrared keeps a canopy's paths alive; without a band there it is not worth it).
  float importance(const Spectrum& s) const { return max_component(s * seen_bins_); }
  // The sun, sky and ground colours of `settings`' bands, and the RGB, from a path's spectrum;
  // the atmosphere's parts after the bands when given.
  void finish(PathSample& out, const Spectrum& radiance,
              const AtmosphereSample* parts = nullptr) const;

  const Scene& scene_;
  const EmbreeScene& embree_;
  SkyModel sky_;
  PlainSurface plain_;
  Medium medium_;
  Vec3f sun_direction_;
  float roulette_threshold_;  // shadow rays adding less than this to a pixel are rouletted
  // The sky's radiance over its sampling density, about (the table's luminance integral, as
  // the largest bin over the luminance): what the sky's shadow-ray roulette weighs a ray by
  // before the ray, and the sky's own radiance, are known.
  float sky_over_pdf_ = 0.0f;
  Spectrum sun_spectrum_;  // irradiance on a surface facing the sun
  Spectrum seen_bins_;     // 1 in bins an output (RGB, a band) sees, 0 elsewhere
  BinSet seen_;            // the same as indices
  int bounce_limit_;
  bool atmosphere_ = false;  // SkyKind::atmosphere: the sky is the medium's light
  // The first film plane of the illumination truth; -1: not asked for.
  int illumination_plane_ = -1;
  // Every ray below the horizon meets the ground (the plain, or a periodic cell's ground): no
  // sky is seen below it.
  bool ground_below_ = false;
  // The one atmosphere by paths: the radiance model whose light haze points take in closed
  // form, their paths adding only what differs from it (a control variate; null: none).
  std::shared_ptr<const RadianceModel> model_;
  // HazeScattering::table: the haze's light but the sun's single scattering; null: traced.
  std::shared_ptr<const ScatteringTable> table_;
  // With the table's hazy sky: surface_sky's luminance from the plain's height, to sample by;
  // under the one atmosphere, its single-scattered sky's (renderer/atmosphere/
  // single_scattered_sky.h).
  std::optional<DirectionTable> hazy_table_;
  // The sky surfaces see (surface_sky from the plain's height), cell by cell: the control
  // variate of open surfaces' skylight. Null where the sky is dark.
  std::optional<SkyIrradiance> sky_model_;
  // Guided paths' field; null: unguided.
  std::shared_ptr<const GuidingField> guide_;
};

}  // namespace landsim::renderer
