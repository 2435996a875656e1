#pragma once
// A scenario: what to render, as read (and validated) from a TOML file. docs/SCENARIO.md
// documents every key. Positions are in the terrain's own coordinates.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/vec3.h"
#include "featuremaps/cover.h"
#include "featuremaps/vegetation_map.h"
#include "renderer/scene.h"
#include "renderer/sensor/sensor_model.h"
#include "renderer/spectra/sensor_band.h"
#include "scenes/scenario/canopy.h"
#include "terrain/dem_loader.h"
#include "trees/species.h"

namespace landsim::scenes {

struct TerrainSettings {
  std::string elevation;  // resolved path: a file, or a GDAL /vsimem/ path for embedded data
  terrain::DemOptions dem;
  Vec3f albedo = renderer::kDefaultGroundAlbedo;
  // Coarser elevation rasters around the grid (resolved paths), in any order.
  std::vector<std::string> context;
  std::vector<std::string> context_locations;  // "file:line:column" of each, for messages
  // RAMI's cyclic boundary: the grid (from its first to its last samples) repeats without end
  // in x and y, and there is no plain beyond it (docs/CANOPIES.md "The periodic cell").
  bool periodic = false;
};

struct SunSettings {
  double elevation_deg = 35.0;
  double azimuth_deg = 135.0;  // clockwise from north
  // On a surface facing the sun; empty: from the sky model (or 3.0 for the gradient sky).
  std::optional<Vec3f> irradiance;
  // Given by date: the day of the year (the Earth-Sun distance of the atmosphere's sun).
  std::optional<int> day_of_year;
};

// A [[views]] table (docs/CAMERAS.md): the camera as the renderer takes it, in terrain
// coordinates, and what places it on the terrain (scenes/builder/view_placement.h).
struct ViewSettings : renderer::View {
  std::string location;  // "file:line:column" of the table, for messages
  // The camera stands this high over the ground below it (position's z is then 0).
  std::optional<double> altitude_above_ground;
  // Orthographic align = "grid": each pixel covers this many cells of the elevation grid
  // each way, its edges on cell edges; 0: not aligned.
  int grid_cells_per_pixel = 0;
  bool has_position = true;   // align = "grid" may leave the position to the grid's centre
  bool aims_at_point = true;  // `target` was given (else the axis is a direction)
  bool has_size = true;       // align = "grid" may leave width and height to the grid
  // The sensor of this view ([sensor] with the view's own `sensor` table over it); empty
  // when the scenario has no [sensor].
  std::optional<renderer::SensorModel> sensor;
};

// Every scenario key's default is declared once: here, or, where the renderer has the
// setting too, taken from the renderer's own default; the loader reads each key with the
// field's value as its default.
struct RenderSection {
  int spp = renderer::RenderSettings{}.spp;
  // Adaptive sampling: `spp` the most a pixel takes (renderer/scene.h RenderSettings).
  double noise_threshold = renderer::RenderSettings{}.noise_threshold;
  std::optional<int> min_spp;  // empty: 16, or spp when that is fewer
  std::uint64_t seed = renderer::RenderSettings{}.seed;
  SampleSequence sampler = renderer::RenderSettings{}.sampler;
  // Seeds the Monte Carlo sampling alone (pixel jitter, light paths); the scene (placement,
  // variants, grass, ground detail) stays the `seed`'s. Empty: the `seed`.
  std::optional<std::uint64_t> sampling_seed;
  int threads = 0;  // 0: every core
  int max_bounces = renderer::RenderSettings{}.max_bounces;
  std::optional<double> exposure_ev100;          // empty: "auto"
  std::vector<double> frames{0.0};               // seconds; wind sway is evaluated at each
  double checkpoint_seconds = 60.0;              // 0: no checkpoints
  trees::Season season = trees::Season::summer;  // winter: leafless
  bool degradation = true;  // range degradation of trees (Weber & Penn section 5)
  double quality = 1.0;     // the paper's quality factor, (0, 1]
  // The memory budget in bytes ("8 GB" in the file); empty: a share of physical memory.
  std::optional<std::uint64_t> max_memory;
  // Georeferenced rasters beside each EXR (docs/OUTPUTS.md "GeoTIFF and ENVI").
  bool geotiff = false;
  bool envi = false;
  // Reflectance-factor layers pi L / E (docs/SENSOR.md): for RGB, every band and channel.
  bool reflectance = false;
  // The atmosphere's parts per pixel (docs/SENSOR.md "The atmosphere's parts per pixel"):
  // path radiance, transmittance, surface radiance, direct and diffuse irradiance and the
  // surface's reflectance factor, for RGB, every band and channel.
  bool atmosphere_layers = false;
  // Illumination truth per pixel (docs/OUTPUTS.md "Illumination truth"): sunlit and the
  // sky-view factor.
  bool illumination_layers = false;
  // Guided paths (docs/PERFORMANCE.md "Guided paths") and their training's share of samples.
  bool guiding = renderer::RenderSettings{}.guiding;
  double guiding_training = renderer::RenderSettings{}.guiding_training;
};

struct WindSettings {
  double speed = 0.0;
  double gust = 0.0;
  double direction_deg = 270.0;  // where the wind comes from, clockwise from north
  double gust_scale = 30.0;      // metres: the size of the gusts that travel with the wind
  int phase_groups = 4;          // sway phases per variant (docs/SPECIES.md "Wind")
  bool active() const { return speed > 0.0 || gust > 0.0; }
};

// Where vegetation grows: a 16-bit vegetation map, or a land-cover class raster with a
// mapping from classes to species bits and grass.
struct FeatureMapSettings {
  std::string vegetation;  // resolved path, or empty
  featuremaps::RasterPlacement placement;
  std::string classes;    // resolved path, or empty
  std::string class_map;  // resolved path, required with classes
  // Ground feature maps: rasters whose non-zero cells carry that material (resolved paths).
  std::string soil, rock, water, road;
};

struct GrassSettings {
  std::string location;                     // "file:line:column" of its table, for messages
  int type = 1;                             // 1-3, the vegetation map's bits 14-15
  std::optional<featuremaps::Cover> cover;  // where it grows besides the feature map
  double density_per_m2 = renderer::GrassType{}.density_per_m2;
  double blade_length = renderer::GrassType{}.blade_length;
  double blade_width = renderer::GrassType{}.blade_width;
  double curvature = renderer::GrassType{}.curvature;
  Vec3f colour = renderer::GrassType{}.reflectance;
};

// The shading variation a scenario has unless [ground] says otherwise.
inline renderer::GroundShading scenario_ground_shading() {
  renderer::GroundShading s;
  s.variation = renderer::kScenarioVariation;
  return s;
}

// Albedo of each ground material (linear RGB).
struct GroundMaterials {
  Vec3f soil{0.20f, 0.15f, 0.10f};
  Vec3f rock{0.35f, 0.33f, 0.30f};
  Vec3f water{0.02f, 0.03f, 0.04f};
  Vec3f road{0.12f, 0.12f, 0.12f};
  // Soil moisture 0-1: the soil colours are dry soil's; moisture darkens their spectra as
  // the measured wet soil is darker (docs/SPECTRAL.md "Soil").
  double soil_moisture = 0.0;
  // Bare ground's spectrum: the measured soils' shape (false), or flat at the albedo's mean,
  // every wavelength alike, as radiative-transfer benchmarks define a Lambertian soil.
  bool flat_soil = false;
  // Variation, rules and texture size (renderer/materials/ground_shading.h); its textures are
  // loaded from `texture_files` (resolved paths, by material id; empty: none) when the scene is
  // built.
  renderer::GroundShading shading = scenario_ground_shading();
  std::array<std::string, renderer::kGroundMaterials> texture_files;
  std::array<std::string, renderer::kGroundMaterials> texture_locations;  // "file:line:col"
  // Reflectance models by material id ([[ground.brdf]]; renderer/materials/ground_brdf.h),
  // where each was given ("file:line:col" of its table; empty: none, Lambert's), for the
  // scene builder's energy check and the plain's model.
  std::array<renderer::GroundBrdf, renderer::kGroundMaterials> brdf{};
  std::array<std::string, renderer::kGroundMaterials> brdf_locations;
  // Whether the material's reflectance is the model's white-sky albedo (the scene builder
  // scales the model to it) or its isotropic parameter.
  std::array<bool, renderer::kGroundMaterials> brdf_white_sky{};
  // Detail below the grid's cells (terrain/surface_detail.h): off by default; per material
  // id the relief's amplitude (metres) and roughness.
  bool detail = false;
  std::array<float, renderer::kGroundMaterials> detail_amplitude{0.3f, 0.0f, 0.0f, 1.0f, 0.3f,
                                                                 0.2f, 0.2f, 0.2f, 0.0f};
  std::array<float, renderer::kGroundMaterials> detail_roughness{0.5f, 0.5f, 0.5f, 0.6f, 0.5f,
                                                                 0.5f, 0.5f, 0.5f, 0.5f};
};

struct SpeciesSettings {
  std::string location;  // "file:line:column" of its table, for messages
  int bit = 0;
  std::optional<featuremaps::Cover> cover;  // where it grows besides the feature map
  trees::Species species;
  int variants = 4;
  double density_per_ha = 200.0;
  double scale_variation = 0.1;
  double colour_variation = 0.0;
  double min_spacing = 0.0;
  bool evergreen = false;  // keeps its leaves in winter and its colour in autumn
  // The variants' ages in years, evenly from the first to the second (equal
  // for one age); negative: the species file's age.
  double age_min = -1.0, age_max = -1.0;
  std::string bark_texture;  // resolved path of an image, or empty
};

// [[objects]] (docs/OBJECTS.md): a mesh file placed on the terrain.
struct ObjectMaterialOverride {
  std::string location;  // "file:line:column" of its table, for messages
  std::string material;  // the mesh material's name
  std::optional<Vec3f> albedo;
  std::optional<float> roughness;
  std::optional<float> metallic;
};

// [objects.place] (docs/OBJECTS.md "Placed by a view"): the object drawn from the seed onto
// ground seen from a view, within a range band and a bearing sector.
struct ObjectSiting {
  std::string location;                         // "file:line:column" of the table, for messages
  std::string view;                             // the view's name
  double range_min = 0.0, range_max = 0.0;      // metres, horizontal, from the camera
  double bearing_min = 0.0, bearing_max = 0.0;  // degrees from the optical axis, clockwise
  bool bearing_given = false;                   // else the view's frame (perspective) or all round
  double min_visible = 0.5;  // share of the object's sample points the camera sees
  bool trees = true;         // trees occlude (their crowns' bounding cylinders, opaque)
  std::uint64_t seed = 0;    // mixed with [render] seed and the randomised image
};

struct ObjectSettings {
  std::string location;           // "file:line:column" of its table
  std::string path;               // "objects[i]" or "objects \"name\"", for messages
  std::string file;               // resolved path of the mesh
  std::string file_location;      // of its `file` key
  std::string position_location;  // of its `position` key
  std::string name;
  double x = 0.0, y = 0.0;   // terrain coordinates
  std::optional<double> z;   // terrain coordinates; empty: standing on the ground
  double heading_deg = 0.0;  // clockwise from north
  double scale = 1.0;
  double unit_scale = 1.0;  // metres per file unit
  bool z_up = false;        // the file's axes: y up and front +z (glTF), or z up and front +y
  bool align_to_ground = false;
  std::optional<double> clear_radius;  // metres; empty: the footprint's radius + 1 m
  std::vector<ObjectMaterialOverride> materials;
  bool random_heading = false;         // `heading = "random"`: drawn from the seed
  std::optional<ObjectSiting> siting;  // placed by a view instead of `position`
  std::size_t copy = 0;                // which of `count` copies (0-based), for the draws
};

// [[bands]]: a sensor band the image set also measures (docs/SPECTRAL.md).
struct BandSettings {
  std::string name;
  std::string description;  // "box 630-690 nm", or "response " and the response file's path
  std::vector<renderer::ResponsePoint> response;
};
// [sensor] (docs/SENSOR.md): the camera's sensor; its channels are rendered as photon
// radiance layers, and each view's digital numbers written beside its EXR.
struct SensorSettings {
  renderer::SensorModel model;
  std::vector<std::vector<renderer::ResponsePoint>> responses;  // per channel
  std::vector<std::string> keys;  // the keys [sensor] gives (a view's table overrides them)
};

// Bands per image set (renderer/transport/integrator.h kMaxBands).
inline constexpr int kMaxSensorBands = 8;

struct Scenario;
// Whether any [[species]] or [[grass]] has a cover (and so needs no feature map).
bool has_cover(const Scenario& s);

// [randomise] (docs/SCENARIO.md "Randomised image sets"): scenario keys drawn per image from
// ranges or lists, as domain randomisation does; each image is the scenario with its draws
// applied as `--set` overrides would be.
struct RandomKey {
  std::string key;       // as --set takes it: "sun.elevation", "objects.0.file"
  std::string location;  // "file:line:column" of its entry
  enum class Kind { range, choose, jitter } kind = Kind::range;
  std::vector<double> lo, hi;        // range: bounds (one per component); jitter: +- hi
  bool integer = false;              // range of integers: drawn inclusive
  bool vector = false;               // range or jitter of an array value
  std::vector<std::string> choices;  // choose: each as TOML text
  std::vector<double> base;          // jitter: the scenario's own value
};
struct RandomiseSettings {
  std::string location;  // of the table
  int images = 1;
  std::uint64_t seed = 0;  // mixed with [render] seed
  std::vector<RandomKey> keys;
  // What each image's scenario is read from again: the text, its source and folder, and the
  // overrides it was read with.
  std::string text, source, base_dir;
  std::vector<std::string> sets;
};

// What a caller chose for one render beyond the scenario's keys (scenes/scenario/
// render_choices.h applies it): samples, threads, image size and the one view to render.
struct RenderChoices {
  std::optional<int> spp;
  std::optional<int> threads;
  std::optional<int> width, height;  // a lone width or height keeps each view's aspect
  std::string view;                  // empty: every view
  std::string source = "--view";     // how messages name the choice of view
};

struct Scenario {
  std::string source;     // the file it came from, for messages
  std::string text_hash;  // FNV-1a 64 of the scenario text, hex (image metadata)
  TerrainSettings terrain;
  std::optional<FeatureMapSettings> featuremaps;
  std::vector<SpeciesSettings> species;
  std::vector<GrassSettings> grass;
  GroundMaterials ground;
  SunSettings sun;
  renderer::Sky sky;    // [sky]: model and turbidity
  renderer::Haze haze;  // [haze]; its base height is the terrain's lowest point
  std::vector<ViewSettings> views;
  RenderSection render;
  WindSettings wind;
  std::vector<ObjectSettings> objects;
  std::vector<CanopySettings> canopies;  // abstract canopies (RAMI), beside or instead of trees
  std::vector<BandSettings> bands;
  std::optional<SensorSettings> sensor;
  std::optional<RandomiseSettings> randomise;
  // The randomised image this scenario is ([randomise], docs/SCENARIO.md), 1-based; 0 when
  // it is not one: it mixes into the objects' draws, so each image places its own.
  std::uint64_t variation = 0;
  std::vector<std::string> variation_sets;  // what that image drew, as --set key=value
  RenderChoices choices;  // those applied (apply_render_choices): each randomised image's too
};

// Limit on frames per scenario (an image set is views x frames images).
inline constexpr int kMaxFrames = 100000;

// Limits that keep a scenario from exhausting memory (see docs/SCENARIO.md).
inline constexpr int kMaxImageSide = 65536;
inline constexpr double kMaxImagePixels = 100e6;
inline constexpr int kMaxSpp = 1 << 20;
// Wind and gust speeds (Weber & Penn section 4.7), in [wind] and on tree's command line alike.
inline constexpr double kMaxWindSpeed = 100.0;

// A scenario's text and where its relative paths resolve: what the Python module keeps to
// change keys (`Scenario.set`) and to write the scenario back out (`to_toml`).
struct ScenarioText {
  std::string text;
  std::string source;    // names the text in messages (a path, or "<default scenario>")
  std::string base_dir;  // relative paths resolve against it
};
// InputError naming the file when it cannot be read.
ScenarioText read_scenario_text(const std::filesystem::path& file);
Scenario parse_scenario(const ScenarioText& t, const std::vector<std::string>& sets = {});
// The scenario's TOML with `sets` applied, as parse_scenario reads it; InputError as there.
std::string scenario_toml(const ScenarioText& t, const std::vector<std::string>& sets = {});

// Throws InputError naming file:line:column, the key and what was expected. `sets` are
// "key=value" overrides applied before reading (`--set`,
// scenes/scenario/detail/scenario_overrides): the same validation, messages naming the override;
// they count in the scenario's hash.
Scenario load_scenario(const std::filesystem::path& file,
                       const std::vector<std::string>& sets = {});
// `source` names the text in messages; relative paths resolve against `base_dir`.
Scenario parse_scenario(std::string_view text, const std::string& source,
                        const std::string& base_dir, const std::vector<std::string>& sets = {});

// A file holding a [sensor] table (`landsim sense --sensor`, docs/SENSOR.md), read as a
// scenario's; other tables are refused. Throws InputError.
SensorSettings load_sensor(const std::filesystem::path& file);

// Checks an image size (also used for command-line overrides); throws InputError.
void check_image_size(int width, int height, const std::string& where);

// A command that needs a camera: InputError when the scenario has no [[views]] (a periodic
// cell measured by landsim brf may have none).
void require_views(const Scenario& s);

}  // namespace landsim::scenes
