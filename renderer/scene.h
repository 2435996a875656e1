#pragma once
// Scene: everything the renderer needs to know, as plain data. Built by scenes/ from a
// scenario, read by the Embree build and by the POV-Ray export, so that a difference
// between two renders is a renderer difference, never a scene difference.
//
// Frame: x east, y north, z up, metres, relative to `origin` (a point in the terrain's own
// coordinates, kept in double precision). Directions are unit vectors.
#include <array>
#include <cmath>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/counter_rng.h"
#include "core/vec3.h"
#include "renderer/camera_model.h"
#include "renderer/materials/ground_brdf.h"
#include "renderer/materials/ground_shading.h"
#include "renderer/spectra/spectral_grid.h"
#include "renderer/spectra/spectrum.h"
#include "terrain/ground_mesh.h"
#include "trees/degradation.h"
#include "trees/geometry.h"

namespace landsim::renderer {

// The terrain's reflectance where nothing else is said (the scenario's [terrain] albedo).
inline constexpr Vec3f kDefaultGroundAlbedo{0.18f, 0.17f, 0.12f};
// Leaves (and grass blades) transmit a little less than they reflect (typical broadleaf
// spectra): transmittance = this x reflectance.
inline constexpr float kLeafTransmittanceRatio = 0.8f;

// A material's measured or modelled spectra (docs/SPECTRAL.md): leaves from PROSPECT-D,
// soils from measured spectra. Where a material has none, the path tracer upsamples its RGB
// (renderer/spectra/spectral_colour.h). Shared: one per species variant, grass type or ground
// material.
struct SpectralOptics {
  Spectrum reflectance;
  Spectrum transmittance;  // zero for opaque materials
};

// A ground material from the ground feature maps (soil, rock, water, road, grass cover).
struct GroundMaterial {
  Vec3f albedo = kDefaultGroundAlbedo;  // Lambertian reflectance, linear RGB
  bool water = false;                   // a Fresnel mirror over a dark diffuse body
};

struct Ground {
  // Material id of context terrain no feature map covers (terrain/context_mesh.h): it takes
  // the plain's albedo, the mean along the grid's edge.
  static constexpr std::uint8_t kSurroundings = 8;

  terrain::GroundMesh mesh;
  Vec3f albedo = kDefaultGroundAlbedo;  // material 0: the terrain's own
  // The plain beyond the grid (renderer/transport/plain.h), and the ground the sky model sees
  // (Hosek-Wilkie's ground albedo): the mean albedo along the grid's edge
  // (scenes/builder/detail/plain_albedo); empty: `albedo`.
  std::optional<Vec3f> edge_albedo;
  Vec3f plain_albedo() const { return edge_albedo.value_or(albedo); }
  // The plain's reflectance spectrum, the edge's mean (scenes/builder/detail/plain_albedo);
  // null: plain_albedo upsampled.
  std::shared_ptr<const SpectralOptics> plain_optics;
  // The plain's height, scene frame z (renderer/transport/plain.h): the mean along the grid's edge
  // (scenes/builder/detail/plain_albedo); empty: the mean of the mesh's rim.
  std::optional<float> plain_height;
  // False: no plain, rays below the horizon see the sky model's (studio scenes: a cutaway
  // looks into the space under its ground).
  bool plain = true;
  std::vector<GroundMaterial> materials;        // further materials, 1-based in the ids below
  std::vector<std::uint8_t> triangle_material;  // per triangle, 0 = `albedo`; may be empty
  // Noise, rules and textures that vary the materials over the ground (ground_shading.h).
  GroundShading shading;
  // Spectra by material id (soils: the measured ones, by moisture); null: the RGB upsampled.
  // The shading's variation multiplies them as it multiplies the albedo.
  std::array<std::shared_ptr<const SpectralOptics>, kGroundMaterials> optics;
  // Reflectance models by material id (ground_brdf.h; Lambert unless the scenario's
  // [[ground.brdf]] says otherwise; water never): the plain takes the surroundings'.
  std::array<GroundBrdf, kGroundMaterials> brdf{};

  // What ground triangle `t` is made of, for every renderer and exporter alike: its material
  // id (0: the terrain's own), and the material of an id.
  std::uint8_t material_id(std::size_t t) const {
    return t < triangle_material.size() ? triangle_material[t] : std::uint8_t{0};
  }
  // The model of material `id`; null where it is Lambert's (the common case, no cost).
  const GroundBrdf* brdf_of(std::uint8_t id) const {
    return id < brdf.size() && !brdf[id].lambertian() ? &brdf[id] : nullptr;
  }
  GroundMaterial material(std::uint8_t id) const {
    return id == 0 || id > materials.size() ? GroundMaterial{albedo, false} : materials[id - 1u];
  }
};

// Grass (Weber & Penn's feature-map grass types): blades as curves in square patches laid
// over the tiles whose vegetation cell selects a grass type.
struct GrassType {
  Vec3f reflectance{0.10f, 0.22f, 0.05f};
  Vec3f transmittance{0.06f, 0.14f, 0.03f};
  double density_per_m2 = 150.0;
  double blade_length = 0.3;   // metres
  double blade_width = 0.004;  // metres
  double curvature = 0.3;      // lean of the blade tip, fraction of its length
};

// Where blades may stand, at the vegetation map's own resolution: the grass type of each
// cell (0: none, and none on road or water), so that a field's edge follows the map, not the
// patches' tiles (renderer/materials/grass_patch.h: grass_blade_kept).
struct GrassMask {
  Vec3 corner;  // south-west corner of cell (0, 0), scene frame (z unused)
  double cell_x = 1.0, cell_y = 1.0;
  int cols = 0, rows = 0;
  std::vector<std::uint8_t> type;  // row 0 southernmost; empty: every blade is kept
};

struct GrassCover {
  double tile = 4.0;  // patch side, metres
  Vec3 corner;        // south-west corner of tile (0, 0), scene frame
  int cols = 0, rows = 0;
  // Per tile, row 0 southernmost: 0 none, else 1-3 (the type at the tile's centre, else the
  // first met among its cells, so that tiles on a field's edge carry blades too).
  std::vector<std::uint8_t> type;
  std::vector<float> height;  // terrain height at the tile centre, scene frame
  std::vector<Vec3f> normal;  // terrain normal there
  std::array<GrassType, 3> types;
  // Per type, the blades' spectra (leaf optics); null: the RGB upsampled.
  std::array<std::shared_ptr<const SpectralOptics>, 3> optics;
  GrassMask mask;
};

struct Sun {
  Vec3 direction{0.0, 0.0, 1.0};  // toward the sun
  // On a surface facing the sun, linear Rec. 709 in lux (Y is illuminance): about 100 klx
  // for a high sun in a clear sky.
  Vec3f irradiance{100000.0f, 96667.0f, 90000.0f};
  double angular_radius = 0.00465;  // radians; the real sun's 0.266 degrees
  // The Earth's distance from the sun on the scenario's date, astronomical units: the
  // atmosphere's sun (SkyKind::atmosphere) is the top-of-atmosphere spectrum over its square.
  double earth_sun_distance = 1.0;
};

// Photometric units: radiance is linear Rec. 709 scaled so that Y = 0.2126 R + 0.7152 G +
// 0.0722 B is luminance in cd/m2; irradiance likewise, Y in lux (docs/ATMOSPHERE.md).

enum class SkyKind {
  hosek_wilkie,  // Hosek and Wilkie 2012/2013: sky dome and sun (the default)
  preetham,      // Preetham, Shirley and Smits 1999, kept for comparison
  gradient,      // a plain gradient from horizon to zenith (tests: zenith = horizon is uniform)
  none,          // no sky: the collimated sun alone (radiative-transfer benchmarks such as RAMI)
  // The one atmosphere (docs/ATMOSPHERE.md "One atmosphere"): space is black, the sun its
  // top-of-atmosphere spectrum, and the sky is what the medium (Haze::column) scatters.
  atmosphere,
};

struct Sky {
  SkyKind model = SkyKind::hosek_wilkie;
  double turbidity = 3.0;
  Vec3f zenith_radiance{3333.0f, 6667.0f, 15000.0f};  // gradient only, cd/m2-scaled
  Vec3f horizon_radiance{15000.0f, 18333.0f, 23333.0f};
};

// The haze: a participating medium (docs/ATMOSPHERE.md "The medium"). Aerosol of exponential
// height profile, extinction at 550 nm sigma(z) = 3.912 / visibility x exp(-(z - base) /
// scale_height) (less the air's own share at the base), scattering a share `albedo` of it
// with its phase function; and, unless `molecular` is off, the air's Rayleigh scattering.
// With `layer`, instead a homogeneous plane-parallel layer (the radiative-transfer checks).
enum class AerosolPhase { henyey_greenstein, isotropic, rayleigh, table, legendre };

struct HazeLayer {
  double optical_depth = 1.0;  // vertical, every wavelength alike
  double top = 1000.0;         // metres: the layer runs from `Haze::base_height` this far up
};

// How the haze's light other than the sun's single scattering reaches a scattering point
// (docs/ATMOSPHERE.md "Two ways to the haze's light").
enum class HazeScattering {
  table,  // tabulated once per render from paths over the plain (fast, noise-free)
  paths,  // traced on every path (exact for any terrain; noisier)
};

// The molecules of the one atmosphere (docs/ATMOSPHERE.md "One atmosphere"): the AFGL 1986
// U.S. Standard profile from the top of the atmosphere down to the ground, its air scattering
// (Rayleigh, Bodhaine et al. 1999) and its ozone absorbing.
struct MolecularColumn {
  bool scattering = true;     // the air's Rayleigh scattering
  bool absorption = true;     // ozone's
  double ozone_column = 0.0;  // Dobson units; 0: the profile's own (345.9)
};

// How the aerosol's density runs with height (Haze::aerosol_profile).
enum class AerosolProfile {
  exponential,  // from the base up, falling by e every scale_height
  uniform,      // constant between uniform_bottom and uniform_top above the base
};

struct Haze {
  bool enabled = false;
  // [atmosphere]: the molecular column is part of the medium and every component, the air's
  // included, acts on every segment (nothing is the sky model's any more).
  std::optional<MolecularColumn> column;
  AerosolProfile aerosol_profile = AerosolProfile::exponential;
  double uniform_bottom = 0.0, uniform_top = 2000.0;  // metres above the base
  // The aerosol's vertical optical depth at 550 nm; when set, instead of the visibility.
  std::optional<double> aerosol_optical_depth;
  bool aerosol = true;  // false: [atmosphere] without an aerosol
  // [atmosphere] by paths: the higher orders through a control variate (renderer/transport/
  // radiance_model.h); off where the model itself is traced.
  bool control_variate = true;
  HazeScattering scattering = HazeScattering::table;
  double visibility = 20000.0;   // meteorological range at the base height, metres
  double scale_height = 1200.0;  // metres
  double base_height = 0.0;      // scene frame z where the visibility holds
  // Height of the base above sea level (the air's density there), metres.
  double base_altitude = 0.0;
  // Single-scattering albedo (a colour, upsampled to a spectrum): OPAC's continental
  // average aerosol (Hess, Koepke and Schult 1998) at 550 nm.
  Vec3f albedo{0.925f, 0.925f, 0.925f};
  AerosolPhase phase = AerosolPhase::henyey_greenstein;
  double asymmetry = 0.703;  // Henyey-Greenstein g (OPAC continental average)
  // AerosolPhase::table: values at scattering angles (degrees, 0 to 180, increasing).
  std::vector<double> phase_angles, phase_values;
  // AerosolPhase::legendre: moments chi_l (chi_0 = 1), DISORT's convention.
  std::vector<double> phase_moments;
  // Aerosol extinction falls with wavelength as (lambda / 550 nm)^-angstrom.
  double angstrom = 1.42;  // OPAC continental average
  // [atmosphere]: a named model's optics by wavelength (renderer/atmosphere/aerosol_model.h,
  // "rami4atm-continental" or "rami4atm-desert") instead of albedo, phase and angstrom;
  // empty: those keys'.
  std::string aerosol_model;
  bool molecular = true;  // the air's Rayleigh scattering
  std::optional<HazeLayer> layer;
};

// A camera (docs/CAMERAS.md). Its optical axis runs from `position` through `target`; the
// image's up is `up` made perpendicular to the axis, then turned by `roll`. Along a vertical
// axis with the default up (+z), the image's right is horizontal and perpendicular to
// `heading` (so a nadir view with heading 0 has north at the top).
struct View {
  std::string name;
  Vec3 position;  // scene frame
  Vec3 target;    // scene frame, any point on the optical axis ahead of the camera
  // Vertical field of view (perspective), or the image circle's angular diameter (fisheye).
  double fov_y_deg = 40.0;
  int width = 640;
  int height = 360;
  // Multiplies the calibrated range every tree's degradation level is chosen for: 1 for
  // renders; Plate 4 (and tests) draw a tree at a range's detail while framing it closely.
  double detail_range_scale = 1.0;
  Vec3 up{0.0, 0.0, 1.0};
  double roll_deg = 0.0;     // clockwise about the axis, seen from behind the camera
  double heading_deg = 0.0;  // clockwise from north
  Lens lens{};
};

// A sensor band (docs/SPECTRAL.md): the image set gets one layer of its band radiance,
// W m^-2 sr^-1, the integral of spectral radiance times its response.
struct SpectralBand {
  std::string name;
  Spectrum weight;  // the response integrated over each bin, nm
};

struct RenderSettings {
  int spp = 16;
  std::uint64_t seed = 1;  // the Monte Carlo sampling's
  // Seeds where each pixel's first sample falls (the truth layers are taken from it): the
  // scene's seed, so that another sampling seed keeps them; empty: `seed`.
  std::optional<std::uint64_t> truth_seed;
  // Adaptive sampling (docs/PERFORMANCE.md "Adaptive sampling"): above 0, a pixel stops once
  // the standard error of its luminance is at most this fraction of its mean, checked after
  // `min_spp` samples and every kAdaptiveBatch after; `spp` is then the most a pixel takes.
  // 0: every pixel takes `spp` samples.
  double noise_threshold = 0.0;
  int min_spp = 16;
  // How each pixel's samples draw their numbers (core/counter_rng.h; docs/PERFORMANCE.md
  // "Sampler"). Sobol since session 19: it reached the million-tree view's 64-sample error
  // in less time than independent samples.
  SampleSequence sampler = SampleSequence::sobol;
  // The most scattering events (surface or haze) a path takes after the camera ray's first
  // vertex; -1: no limit, paths end by Russian roulette alone (unbiased, the default). A
  // limit is a bias (0: direct light only), kept for comparisons.
  int max_bounces = -1;
  // The preview PNG's exposure value at ISO 100; empty: automatic (renderer/output/exposure.h).
  // The EXR stays in cd/m2 either way.
  std::optional<double> exposure_ev100;
  // Range degradation (Weber & Penn section 5) of trees, and stochastic blending of tree and
  // grass levels; off: every tree at full detail, grass levels switched abruptly.
  bool degradation = true;
  // Benchmarks only: false snaps each tree to its ladder step's level (no blending), to
  // measure the popping that blending removes.
  bool degradation_blend = true;
  // The atmosphere's parts per pixel (renderer/output/atmosphere_layers.h): path radiance,
  // transmittance, surface radiance, direct and diffuse irradiance; each sample traces one
  // more path for the diffuse irradiance.
  bool atmosphere_layers = false;
  // Illumination truth per pixel (renderer/output/illumination_layers.h): sunlit and the
  // sky-view factor; one shadow ray and a few sky rays more at each sample's first surface.
  bool illumination_layers = false;
  // Guided paths (renderer/guiding/; docs/PERFORMANCE.md "Guided paths"): training passes
  // learn where each region's light comes from, and the render's diffuse vertices sample
  // there as well as by their BSDF. `guiding_training`: the training passes' samples as a
  // share of the render's (spp x pixels); their image is not kept.
  bool guiding = false;
  double guiding_training = 0.125;
};

// One unique tree (a species variant), stored once and instanced many times.
class BarkTexture;

struct TreePrototype {
  trees::TreeGeometry geometry;  // tree base at the origin, z up, metres
  Vec3f bark_albedo = trees::TreeColours{}.bark;
  std::shared_ptr<const BarkTexture> bark_texture;  // optional, modulates bark_albedo
  Vec3f leaf_reflectance = trees::TreeColours{}.leaf;
  Vec3f leaf_transmittance = trees::TreeColours{}.leaf * kLeafTransmittanceRatio;
  // Leaf colour factor at vigour 0 (species weak-leaf colour over leaf colour); leaves of
  // vigour v take lerp(leaf_weak_tint, 1, v) times the colours above.
  Vec3f leaf_weak_tint{1.0f, 1.0f, 1.0f};
  Vec3f leaf_tint(float vigour) const {
    return leaf_weak_tint + (Vec3f{1.0f, 1.0f, 1.0f} - leaf_weak_tint) * vigour;
  }
  // The leaves' spectra (PROSPECT-D, or the colour in the visible joined to a leaf's near
  // infrared: docs/SPECTRAL.md); the vigour tint multiplies them; null: the RGB upsampled.
  std::shared_ptr<const SpectralOptics> leaf_optics;
  std::uint16_t species = 0;  // index in the scenario's species table
  // An abstract canopy's leaf cloud (RAMI): its leaves are the discs of `geometry`'s leaf
  // points at every range, as the benchmark defines them (no polygons, no degradation).
  bool leaf_discs = false;
  // The paper's s and d for this tree (quality, season, evergreen).
  trees::DegradationFactors degradation;

  // The species' colours as they are: bark, leaves (transmitting kLeafTransmittanceRatio of
  // their reflectance), and the second leaf colour (weak leaves, or a harmonic species'
  // flowers) as the tint at vigour 0.
  void dress(const trees::TreeColours& c) {
    bark_albedo = c.bark;
    leaf_reflectance = c.leaf;
    leaf_transmittance = c.leaf * kLeafTransmittanceRatio;
    leaf_weak_tint = {c.leaf.x > 0 ? c.leaf_weak.x / c.leaf.x : 1.0f,
                      c.leaf.y > 0 ? c.leaf_weak.y / c.leaf.y : 1.0f,
                      c.leaf.z > 0 ? c.leaf_weak.z / c.leaf.z : 1.0f};
  }
};

struct TreeInstance {
  std::uint32_t prototype = 0;
  Vec3 position;          // trunk base, scene frame
  double rotation = 0.0;  // about z, radians
  double scale = 1.0;
  // The whole tree's lean in the wind (scenes/builder/wind_field.h): a turn about the trunk base
  // after the rotation, as axis x angle (radians); zero: upright.
  Vec3 lean{};
  bool leans() const { return lean.x != 0.0 || lean.y != 0.0 || lean.z != 0.0; }
  // The lean as a rotation of `v`.
  Vec3 apply_lean(const Vec3& v) const {
    const double angle = length(lean);
    return angle == 0.0 ? v : rotate_about(v, lean / angle, angle);
  }
};

// Scene objects (vehicles, structures; docs/OBJECTS.md): meshes read from files, each file
// once as a prototype, placed by instances with their own materials.
class ObjectTexture;

// A mesh material: a diffuse base colour under a GGX glossy coat, as glTF's
// metallic-roughness model has it (renderer/transport/glossy.h).
struct ObjectMaterial {
  Vec3f base_colour{0.8f, 0.8f, 0.8f};  // linear RGB
  float roughness = 0.5f;               // perceptual: GGX alpha = roughness^2
  float metallic = 0.0f;
  std::shared_ptr<const ObjectTexture> texture;  // optional, multiplies base_colour
};

struct ObjectPrototype {
  std::string file;
  // Object frame: metres, z up, front toward +y; the placement's origin at (0, 0, 0).
  std::vector<Vec3f> vertices, normals;
  std::vector<float> uvs;  // u, v per vertex (v up), or empty
  std::vector<std::uint32_t> indices;
  std::vector<std::uint32_t> triangle_material;  // per triangle
  std::vector<std::string> material_names;
  std::size_t triangle_count() const { return indices.size() / 3; }
};

struct ObjectInstance {
  std::string name;
  std::uint32_t prototype = 0;
  // Object frame -> scene frame: column-major 3 x 4, a rotation times a uniform scale, then
  // the translation.
  std::array<double, 12> transform{1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0};
  std::vector<ObjectMaterial> materials;  // one per prototype material, overrides applied
  // A direction of the object's frame in the scene's (the transform's linear part; normals
  // transform alike, the scale being uniform).
  Vec3 turn(const Vec3& d) const {
    const auto& m = transform;
    return {m[0] * d.x + m[3] * d.y + m[6] * d.z, m[1] * d.x + m[4] * d.y + m[7] * d.z,
            m[2] * d.x + m[5] * d.y + m[8] * d.z};
  }
  Vec3 apply(const Vec3f& p) const {
    return turn(Vec3(p)) + Vec3{transform[9], transform[10], transform[11]};
  }
};

// RAMI's cyclic boundary (docs/CANOPIES.md "The periodic cell"): the scene repeats without end
// in x and y with the period of this cell (scene frame); a ray leaving it through a side
// enters again through the opposite one (renderer/transport/periodic_cell.h). `top`: nothing
// stands above it, so a ray rising past it has left for good.
struct PeriodicCell {
  double x0 = 0.0, y0 = 0.0, x1 = 0.0, y1 = 0.0;
  double top = 0.0;
};

struct Scene {
  Vec3 origin;  // terrain coordinates of the scene frame's (0, 0, 0)
  // The terrain's coordinate reference system (well-known text; empty for a local grid),
  // for georeferenced outputs.
  std::string crs_wkt;
  Ground ground;
  std::vector<TreePrototype> prototypes;
  std::vector<TreeInstance> instances;
  std::vector<ObjectPrototype> object_prototypes;
  std::vector<ObjectInstance> objects;
  GrassCover grass;
  Sun sun;
  Sky sky;
  Haze haze;
  std::vector<View> views;
  std::optional<PeriodicCell> periodic;  // empty: the scene is what is drawn, and the plain
  RenderSettings settings;
  std::vector<SpectralBand> bands;
  // What the wavelength bins stand for: their means, or a monochromatic run's wavelength
  // (renderer/spectra/spectral_grid.h; the medium and the sun are evaluated at it).
  SpectralGrid spectral_grid;
};

}  // namespace landsim::renderer
