#include "scenes/builder/scene_builder.h"

#include "renderer/camera.h"

#include "renderer/spectra/vegetation_optics.h"

#include <fmt/format.h>
#include <spdlog/spdlog.h>
#include <tbb/parallel_for.h>

#include <cmath>
#include <map>
#include <numbers>

#include "core/counter_rng.h"
#include "core/input_error.h"
#include "featuremaps/placement.h"
#include "renderer/atmosphere/sky.h"
#include "renderer/atmosphere/standard_atmosphere.h"
#include "renderer/materials/bark_texture.h"
#include "scenes/builder/detail/camera_check.h"
#include "scenes/builder/detail/context_terrain.h"
#include "scenes/builder/detail/grass_cover.h"
#include "scenes/builder/detail/ground_models.h"
#include "scenes/builder/detail/leaf_cloud.h"
#include "scenes/builder/detail/periodic_cell.h"
#include "scenes/builder/detail/plain_albedo.h"
#include "scenes/builder/detail/scene_foundation.h"
#include "scenes/builder/detail/scene_objects.h"
#include "scenes/builder/detail/tree_variant.h"
#include "scenes/builder/detail/vegetation_input.h"
#include "scenes/builder/wind_field.h"
#include "scenes/scenario/sensor_bands.h"
#include "terrain/context_mesh.h"
#include "terrain/ground_mesh.h"
#include "terrain/terrain_field.h"

namespace landsim::scenes {
namespace {

void add_trees(const Scenario& s, const featuremaps::VegetationMap& map,
               const terrain::ElevationGrid& grid, const terrain::SurfaceDetail* relief,
               double time, VariantCache* reuse, renderer::Scene& scene) {
  const std::uint64_t seed = s.render.seed;
  std::vector<featuremaps::SpeciesPlacement> placements;
  for (const SpeciesSettings& sp : s.species) {
    placements.push_back(
        {sp.bit, sp.density_per_ha, sp.min_spacing, sp.variants, sp.scale_variation});
  }
  const std::vector<featuremaps::PlacedTree> placed =
      featuremaps::place_trees(map, grid, placements, seed);

  // Every variant in use, once per phase group its trees fall in (one group without wind),
  // in (species, variant, group) order; generated in parallel.
  const auto group_of = [&](const featuremaps::PlacedTree& t) {
    return s.wind.active() ? phase_group(s.wind, t.x, t.y, seed) : 0u;
  };
  using Key = std::array<std::uint32_t, 3>;  // species, variant, phase group
  std::map<Key, std::uint32_t> prototype_of;
  for (const featuremaps::PlacedTree& t : placed)
    prototype_of.emplace(Key{t.species, t.variant, group_of(t)}, 0);
  std::vector<Key> keys;
  for (auto& [key, index] : prototype_of) {
    index = static_cast<std::uint32_t>(keys.size());
    keys.push_back(key);
  }
  // Bark textures, read once per species and shared by its variants.
  std::vector<std::shared_ptr<const renderer::BarkTexture>> textures(s.species.size());
  for (std::size_t k = 0; k < s.species.size(); ++k) {
    if (!s.species[k].bark_texture.empty())
      textures[k] = renderer::load_bark_texture(s.species[k].bark_texture);
  }
  scene.prototypes.resize(keys.size());
  tbb::parallel_for(std::size_t{0}, keys.size(), [&](std::size_t i) {
    const auto [species, variant, group] = keys[i];
    if (reuse != nullptr) {
      const auto found = reuse->trees.find({species, variant, time, group});
      if (found != reuse->trees.end()) {
        scene.prototypes[i] = std::move(found->second);
        return;
      }
    }
    scene.prototypes[i] = detail::make_tree_variant(s, species, variant, time, group);
  });
  for (std::size_t i = 0; i < keys.size(); ++i)
    scene.prototypes[i].bark_texture = textures[keys[i][0]];
  scene.instances.reserve(placed.size());
  for (const featuremaps::PlacedTree& t : placed) {
    // With detail, a tree stands on the relief, not on the grid's facet beneath it.
    const double z = t.z + (relief != nullptr ? relief->displacement(t.x, t.y) : 0.0);
    scene.instances.push_back({prototype_of.at({t.species, t.variant, group_of(t)}),
                               Vec3{t.x, t.y, z} - scene.origin, t.rotation, t.scale,
                               tree_lean(s.wind, t.x, t.y, time)});
  }
}

// Grass tiles stand on the relief at their centres.
void lift_grass(const terrain::SurfaceDetail& relief, renderer::Scene& scene) {
  renderer::GrassCover& g = scene.grass;
  for (int r = 0; r < g.rows; ++r)
    for (int c = 0; c < g.cols; ++c) {
      const std::size_t k = static_cast<std::size_t>(r) * g.cols + c;
      if (g.type[k] == 0) continue;
      const double x = scene.origin.x + g.corner.x + (c + 0.5) * g.tile;
      const double y = scene.origin.y + g.corner.y + (r + 0.5) * g.tile;
      g.height[k] += static_cast<float>(relief.displacement(x, y));
    }
}

using detail::GroundRasters;
using detail::MaterialRaster;

// The material the ground maps give a point, by priority: road, water, rock, soil, then the
// ground under a grass type [[grass]] defines; none where no map says.
std::optional<std::uint8_t> mapped_material(const Scenario& s, const GroundRasters& rasters,
                                            const featuremaps::VegetationMap* map, double x,
                                            double y) {
  for (std::size_t m = 0; m < rasters.size(); ++m)
    if (rasters[m].covers(x, y)) return static_cast<std::uint8_t>(m + 1);
  if (map == nullptr) return std::nullopt;
  const auto cell = map->cell_at(x, y);
  if (!cell || cell->grass_type() == 0) return std::nullopt;
  for (const GrassSettings& g : s.grass)
    if (g.type == cell->grass_type()) return static_cast<std::uint8_t>(4 + g.type);
  return std::nullopt;
}

// Ground materials per triangle (at its centre) from the ground maps.
void add_ground_materials(const Scenario& s, const featuremaps::VegetationMap* map,
                          const GroundRasters& rasters, renderer::Scene& scene) {
  const bool any_raster = std::any_of(rasters.begin(), rasters.end(),
                                      [](const MaterialRaster& m) { return m.grid.has_value(); });
  if (!any_raster && (map == nullptr || s.grass.empty())) return;
  renderer::Ground& ground = scene.ground;
  const terrain::GroundMesh& mesh = ground.mesh;
  // Context triangles keep kSurroundings where no map says otherwise.
  if (ground.triangle_material.empty()) ground.triangle_material.assign(mesh.triangle_count(), 0);
  tbb::parallel_for(std::size_t{0}, mesh.triangle_count(), [&](std::size_t t) {
    const Vec3f a = mesh.vertices[mesh.indices[3 * t]], b = mesh.vertices[mesh.indices[3 * t + 1]],
                c = mesh.vertices[mesh.indices[3 * t + 2]];
    const Vec3 centre = Vec3((a + b + c) / 3.0f) + scene.origin;
    if (const auto id = mapped_material(s, rasters, map, centre.x, centre.y))
      ground.triangle_material[t] = *id;
  });
}

constexpr std::uint8_t kSurroundings = renderer::Ground::kSurroundings;

// The ground materials by id: 1 road, 2 water, 3 rock, 4 soil, 5-7 the ground under grass
// types 1-3, 8 context terrain (its albedo is set once the grid's edge is known).
void set_ground_materials(const Scenario& s, renderer::Scene& scene) {
  scene.ground.materials = {{s.ground.road, false},
                            {s.ground.water, true},
                            {s.ground.rock, false},
                            {s.ground.soil, false}};
  for (int t = 0; t < 3; ++t) {
    // Seen from afar grass is its colour; the ground under it takes a darker shade of it.
    scene.ground.materials.push_back(
        {scene.grass.types[static_cast<std::size_t>(t)].reflectance * 0.9f, false});
  }
  scene.ground.materials.push_back({scene.ground.albedo, false});
}

// The spectra of the materials that have their own (docs/SPECTRAL.md "Materials"): bare
// ground (the terrain's own and soil) from the measured soils, the ground under grass and
// the blades as vegetation; rock, road, water and the surroundings upsample their colours.
void set_spectral_optics(const Scenario& s, renderer::Scene& scene) {
  auto& optics = scene.ground.optics;
  const double moisture = s.ground.soil_moisture;
  const auto soil = [&](const Vec3f& albedo) {
    if (!s.ground.flat_soil) return renderer::soil_optics(albedo, moisture);
    renderer::SpectralOptics flat;  // every wavelength the albedo's mean (RAMI's soils)
    flat.reflectance = renderer::Spectrum::constant((albedo.x + albedo.y + albedo.z) / 3.0f);
    return flat;
  };
  optics[0] = std::make_shared<renderer::SpectralOptics>(soil(scene.ground.albedo));
  optics[4] = std::make_shared<renderer::SpectralOptics>(soil(scene.ground.materials[3].albedo));
  for (std::size_t t = 0; t < 3; ++t) {
    const renderer::GrassType& g = scene.grass.types[t];
    scene.grass.optics[t] = std::make_shared<renderer::SpectralOptics>(
        renderer::coloured_leaf_optics(g.reflectance, g.transmittance));
    const Vec3f under = scene.ground.materials[4 + t].albedo;
    optics[5 + t] =
        std::make_shared<renderer::SpectralOptics>(renderer::coloured_leaf_optics(under, {}));
  }
}

// The ground mesh: the grid's own, or with context grids the grid and its surroundings; in
// the latter case context triangles take kSurroundings (feature maps may override it).
void add_ground_mesh(const Scenario& s, const terrain::ElevationGrid& grid,
                     const std::vector<renderer::View>& views, const terrain::SurfaceDetail* relief,
                     renderer::Scene& scene) {
  if (s.terrain.context.empty() && relief == nullptr) {
    scene.ground.mesh = terrain::build_ground_mesh(grid, scene.origin);
    return;
  }
  const terrain::TerrainField field = detail::context_terrain(s, grid);
  terrain::ContextMeshOptions options = context_mesh_options(views, grid.min_height());
  options.detail = relief;
  terrain::ContextMesh m = terrain::build_context_mesh(field, scene.origin, options);
  scene.ground.mesh = std::move(m.mesh);
  scene.ground.triangle_material = std::move(m.from_context);
  for (std::uint8_t& id : scene.ground.triangle_material) id = id != 0 ? kSurroundings : 0;
}

// The scenario's shading variation, seeded from the render seed, with its textures read
// (a texture shared by several materials is read once).
renderer::GroundShading ground_shading(const Scenario& s) {
  renderer::GroundShading shading = s.ground.shading;
  shading.seed = mix64(s.render.seed ^ 0x67726f756e64ULL);
  std::map<std::string, std::shared_ptr<const renderer::GroundTexture>> read;
  for (std::size_t id = 0; id < s.ground.texture_files.size(); ++id) {
    const std::string& path = s.ground.texture_files[id];
    if (path.empty()) continue;
    auto& texture = read[path];
    try {
      if (!texture) texture = renderer::load_bark_texture(path, "ground texture");
    } catch (const InputError& e) {
      throw InputError(s.ground.texture_locations[id] + ": [ground] textures: " + e.what());
    }
    shading.textures[id] = texture;
  }
  return shading;
}

// [ground] detail: per grid sample the amplitude and roughness of its material.
std::optional<terrain::SurfaceDetail> surface_detail(const Scenario& s,
                                                     const terrain::ElevationGrid& grid,
                                                     const GroundRasters& rasters,
                                                     const featuremaps::VegetationMap* map) {
  if (!s.ground.detail) return std::nullopt;
  const auto cells = static_cast<std::size_t>(grid.cols()) * static_cast<std::size_t>(grid.rows());
  std::vector<float> amplitude(cells), roughness(cells);
  tbb::parallel_for(0, grid.rows(), [&](int r) {
    for (int c = 0; c < grid.cols(); ++c) {
      const std::size_t id =
          mapped_material(s, rasters, map, grid.x_of_col(c), grid.y_of_row(r)).value_or(0);
      const std::size_t i = static_cast<std::size_t>(r) * grid.cols() + c;
      amplitude[i] = s.ground.detail_amplitude[id];
      roughness[i] = s.ground.detail_roughness[id];
    }
  });
  return terrain::SurfaceDetail(grid, std::move(amplitude), std::move(roughness),
                                mix64(s.render.seed ^ 0x72656c696566ULL));
}

}  // namespace

terrain::ContextMeshOptions context_mesh_options(const std::vector<renderer::View>& views,
                                                 double lowest_ground) {
  terrain::ContextMeshOptions o;
  double pixel = 1.0;        // the finest pixel of any view, radians
  double calibration = 0.0;  // the largest of r2 / distance (Weber & Penn section 5)
  for (const renderer::View& v : views) {
    o.views.push_back({v.position.x, v.position.y});
    if (v.lens.projection == renderer::Projection::perspective) {
      pixel = std::min(pixel, v.fov_y_deg * std::numbers::pi / 180.0 / v.height);
      calibration = std::max(calibration, trees::calibrated_range(1.0, v.height, v.fov_y_deg));
      continue;
    }
    // Other models by their footprint at the ground below (an orthographic pixel is the same
    // size at every range: as seen from the camera's height).
    const double d = v.lens.projection == renderer::Projection::orthographic
                         ? std::max(1.0, v.position.z - lowest_ground)
                         : 1.0;
    const double r2 = renderer::calibrated_view_range(v, d) / d;
    pixel = std::min(pixel, r2 * 0.06 * std::numbers::pi / 180.0);
    calibration = std::max(calibration, r2);
  }
  o.range_factor = std::clamp(1.0 / (kContextCellPixels * pixel), 2.0, 400.0);
  // Detail cells of r2 / kDetailRange metres at calibrated range r2.
  o.detail_factor = std::clamp(kDetailRange / std::max(calibration, 1e-9), 2.0, 400.0);
  return o;
}

Vec3 sun_direction(double elevation_deg, double azimuth_deg) {
  const double el = elevation_deg * std::numbers::pi / 180.0;
  const double az = azimuth_deg * std::numbers::pi / 180.0;
  return {std::sin(az) * std::cos(el), std::cos(az) * std::cos(el), std::sin(el)};
}

renderer::Scene build_scene(const Scenario& scenario, double time, VariantCache* reuse) {
  const detail::SceneFoundation foundation = detail::lay_foundation(scenario);
  const terrain::ElevationGrid& grid = foundation.grid;
  const GroundRasters& rasters = foundation.rasters;
  const std::optional<featuremaps::VegetationMap>& map = foundation.map;
  renderer::Scene scene;
  scene.origin = grid.centre();
  scene.crs_wkt = grid.crs_wkt();
  const std::optional<terrain::SurfaceDetail> relief =
      surface_detail(scenario, grid, rasters, map ? &*map : nullptr);
  add_ground_mesh(scenario, grid, foundation.views, relief ? &*relief : nullptr, scene);
  scene.ground.albedo = scenario.terrain.albedo;
  scene.ground.shading = ground_shading(scenario);
  scene.sun.direction = sun_direction(scenario.sun.elevation_deg, scenario.sun.azimuth_deg);
  scene.sky = scenario.sky;
  // The Earth-Sun distance of the date (the atmosphere's sun); a sun given by its angles alone
  // is at the mean distance.
  if (scenario.sun.day_of_year)
    scene.sun.earth_sun_distance = renderer::earth_sun_distance(*scenario.sun.day_of_year);
  if (scenario.sun.irradiance) {
    scene.sun.irradiance = *scenario.sun.irradiance;
  } else {
    scene.sun.irradiance =
        renderer::sun_irradiance(scenario.sky, scenario.sun.elevation_deg, scene.sun.angular_radius,
                                 scene.sun.earth_sun_distance);
  }
  scene.haze = scenario.haze;
  scene.haze.base_height =
      grid.min_height() - scene.origin.z;        // the visibility holds at the lowest ground
  scene.haze.base_altitude = grid.min_height();  // the air's density there
  detail::warn_cameras_below_ground(scenario, foundation.views, grid);
  scene.views = foundation.views_around(scene.origin);
  scene.settings.spp = scenario.render.spp;
  scene.settings.seed = scenario.render.sampling_seed.value_or(scenario.render.seed);
  scene.settings.truth_seed = scenario.render.seed;
  scene.settings.noise_threshold = scenario.render.noise_threshold;
  scene.settings.sampler = scenario.render.sampler;
  // At most spp, which --spp may have lowered after the file was read.
  scene.settings.min_spp = std::min(
      scenario.render.spp, scenario.render.min_spp.value_or(renderer::RenderSettings{}.min_spp));
  scene.settings.max_bounces = scenario.render.max_bounces;
  scene.settings.exposure_ev100 = scenario.render.exposure_ev100;
  scene.settings.degradation = scenario.render.degradation;
  scene.settings.atmosphere_layers = scenario.render.atmosphere_layers;
  scene.settings.illumination_layers = scenario.render.illumination_layers;
  scene.settings.guiding = scenario.render.guiding;
  scene.settings.guiding_training = scenario.render.guiding_training;
  for (const BandSettings& b : scenario.bands)
    scene.bands.push_back(renderer::sensor_band(b.name, b.response));
  // The sensor's channels, in photons (docs/SENSOR.md), after the bands.
  if (scenario.sensor)
    for (std::size_t c = 0; c < scenario.sensor->responses.size(); ++c)
      scene.bands.push_back(renderer::photon_band(
          photon_layer(scenario.sensor->model.channels[c].name), scenario.sensor->responses[c]));
  if (map && !scenario.species.empty())
    add_trees(scenario, *map, grid, relief ? &*relief : nullptr, time, reuse, scene);
  detail::add_canopies(scenario, grid, scene);
  // Objects after the trees: each clears the trunks within its radius.
  detail::add_objects(scenario, scene, reuse != nullptr ? &reuse->meshes : nullptr);
  if (map) {
    if (!scenario.species.empty()) detail::warn_cameras_inside_trees(scenario, scene);
    if (!scenario.grass.empty()) {
      const auto blocked = [&](double x, double y) { return foundation.blocks_grass(x, y); };
      scene.grass = detail::grass_cover(scenario, *map, grid, scene.origin, blocked);
      if (relief) lift_grass(*relief, scene);
    }
  }
  if (scenario.featuremaps || has_cover(scenario))
    add_ground_materials(scenario, map ? &*map : nullptr, rasters, scene);
  set_ground_materials(scenario, scene);
  const detail::EdgeGround edge = detail::edge_ground(scene.ground, grid, scene.origin);
  scene.ground.edge_albedo = edge.albedo;
  // With context grids the drawn ground ends at their rim, whose mean the renderer takes.
  if (scenario.terrain.context.empty())
    scene.ground.plain_height = detail::edge_height(grid, scene.origin);
  detail::warn_cameras_under_the_plain(scenario, scene);
  scene.ground.materials[kSurroundings - 1].albedo = scene.ground.plain_albedo();
  set_spectral_optics(scenario, scene);
  // The plain and the surroundings continue the edge's spectrum, not only its colour.
  scene.ground.plain_optics = detail::edge_optics(scene.ground, edge);
  scene.ground.optics[kSurroundings] = scene.ground.plain_optics;
  detail::set_ground_models(scenario, edge, scene);
  if (scenario.terrain.periodic) detail::make_periodic(grid, scene);
  return scene;
}

}  // namespace landsim::scenes
