#include "scenes/scene_builder.h"

#include <fmt/format.h>
#include <spdlog/spdlog.h>
#include <tbb/parallel_for.h>

#include <cmath>
#include <map>
#include <numbers>

#include "core/counter_rng.h"
#include "core/input_error.h"
#include "featuremaps/class_mapping.h"
#include "featuremaps/placement.h"
#include "renderer/bark_texture.h"
#include "renderer/sky.h"
#include "terrain/ground_mesh.h"

namespace landsim::scenes {
namespace {

// Leaves transmit a little less than they reflect (typical broadleaf spectra).
constexpr float kLeafTransmittanceRatio = 0.8f;

featuremaps::VegetationMap vegetation_map(const FeatureMapSettings& f, std::uint64_t seed) {
  if (!f.vegetation.empty()) return featuremaps::load_vegetation_map(f.vegetation, f.placement);
  terrain::DemOptions options;
  options.cell_size = f.placement.cell_size;
  options.origin = f.placement.origin;
  const terrain::ElevationGrid classes = terrain::load_elevation(f.classes, options);
  return featuremaps::build_vegetation_map(classes, featuremaps::load_class_mapping(f.class_map),
                                           seed);
}

std::uint64_t variant_seed(std::uint64_t seed, int bit, std::uint32_t variant) {
  return hash_combine(hash_combine(seed, static_cast<std::uint64_t>(bit)), variant);
}

renderer::TreePrototype make_prototype(const SpeciesSettings& sp, std::uint32_t species_index,
                                       std::uint32_t variant, double time, const Scenario& s) {
  renderer::TreePrototype p;
  const std::uint64_t vs = variant_seed(s.render.seed, sp.bit, variant);
  const std::string& season = s.render.season;
  trees::TreeOptions options;
  options.seed = vs;
  options.time = time;
  options.quality = s.render.quality;
  // Measured-growth ages: evenly from the youngest to the oldest across the variants.
  if (sp.age_min >= 0.0)
    options.age = sp.variants > 1
                      ? sp.age_min + (sp.age_max - sp.age_min) * variant / (sp.variants - 1)
                      : sp.age_min;
  options.wind_speed = s.wind.speed;
  options.wind_gust = s.wind.gust;
  p.geometry = trees::generate(sp.species, options).geometry;
  p.degradation = trees::degradation_factors(
      s.render.quality, trees::season_from_name(season).value_or(trees::Season::summer),
      sp.evergreen);
  p.species = static_cast<std::uint16_t>(species_index);
  p.bark_albedo = sp.species.colours.bark;
  // Per-variant colour variation: one brightness factor and a slight hue shift.
  const CounterRng r(vs, 17, 0);
  const auto v = static_cast<float>(sp.colour_variation);
  const Vec3f factor{1.0f + v * (2.0f * r.uniform(0) - 1.0f),
                     1.0f + v * (2.0f * r.uniform(1) - 1.0f),
                     1.0f + v * (2.0f * r.uniform(2) - 1.0f)};
  const float brightness = 1.0f + v * (2.0f * r.uniform(3) - 1.0f);
  p.leaf_reflectance = sp.species.colours.leaf * factor * brightness;
  if (!sp.evergreen) {
    if (season == "spring") {
      p.leaf_reflectance = p.leaf_reflectance * Vec3f{1.25f, 1.3f, 0.7f};  // young, yellower green
    } else if (season == "autumn") {
      // Each variant turns its own way between yellow, orange and red.
      static constexpr Vec3f kAutumn[3] = {
          {0.45f, 0.35f, 0.05f}, {0.45f, 0.18f, 0.03f}, {0.35f, 0.07f, 0.03f}};
      p.leaf_reflectance = kAutumn[std::min(2, static_cast<int>(r.uniform(4) * 3.0f))] * brightness;
    } else if (season == "winter") {
      p.geometry.group(trees::Group::leaves) = trees::GroupGeometry{};  // leafless
    }
  }
  p.leaf_transmittance = p.leaf_reflectance * kLeafTransmittanceRatio;
  const Vec3f& leaf = sp.species.colours.leaf;
  const Vec3f& weak = sp.species.colours.leaf_weak;
  p.leaf_weak_tint = {leaf.x > 0 ? weak.x / leaf.x : 1.0f, leaf.y > 0 ? weak.y / leaf.y : 1.0f,
                      leaf.z > 0 ? weak.z / leaf.z : 1.0f};
  return p;
}

void add_trees(const Scenario& s, const featuremaps::VegetationMap& map,
               const terrain::ElevationGrid& grid, double time, renderer::Scene& scene) {
  const std::uint64_t seed = s.render.seed;
  std::vector<featuremaps::SpeciesPlacement> placements;
  for (const SpeciesSettings& sp : s.species) {
    placements.push_back(
        {sp.bit, sp.density_per_ha, sp.min_spacing, sp.variants, sp.scale_variation});
  }
  const std::vector<featuremaps::PlacedTree> placed =
      featuremaps::place_trees(map, grid, placements, seed);

  // Every variant in use, once, in (species, variant) order; generated in parallel.
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> prototype_of;
  for (const featuremaps::PlacedTree& t : placed)
    prototype_of.emplace(std::pair{t.species, t.variant}, 0);
  std::vector<std::pair<std::uint32_t, std::uint32_t>> keys;
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
    const auto [species, variant] = keys[i];
    scene.prototypes[i] = make_prototype(s.species[species], species, variant, time, s);
  });
  for (std::size_t i = 0; i < keys.size(); ++i)
    scene.prototypes[i].bark_texture = textures[keys[i].first];
  scene.instances.reserve(placed.size());
  for (const featuremaps::PlacedTree& t : placed) {
    scene.instances.push_back({prototype_of.at({t.species, t.variant}),
                               Vec3{t.x, t.y, t.z} - scene.origin, t.rotation, t.scale});
  }
}

// A feature map that misses the terrain entirely is almost certainly misplaced.
void check_overlap(const featuremaps::VegetationMap& map, const terrain::ElevationGrid& grid,
                   const std::string& path) {
  const std::array<double, 4> b = map.bounds();
  const double west = grid.transform().origin_x, north = grid.transform().origin_y;
  const double east = west + grid.cols() * grid.transform().cell_size_x;
  const double south = north - grid.rows() * grid.transform().cell_size_y;
  if (b[2] <= west || b[0] >= east || b[3] <= south || b[1] >= north) {
    throw InputError(fmt::format(
        "{}: feature map ({:.1f}, {:.1f})-({:.1f}, {:.1f}) does not overlap the terrain "
        "({:.1f}, {:.1f})-({:.1f}, {:.1f}); check its georeferencing or [featuremaps] origin",
        path, b[0], b[1], b[2], b[3], west, south, east, north));
  }
}

// Grass patches cover square tiles of this side (metres).
constexpr double kGrassTile = 4.0;

void add_grass(const Scenario& s, const featuremaps::VegetationMap& map,
               const terrain::ElevationGrid& grid, renderer::Scene& scene) {
  renderer::GrassCover& cover = scene.grass;
  std::array<bool, 3> defined{};
  for (const GrassSettings& g : s.grass) {
    renderer::GrassType& t = cover.types[static_cast<std::size_t>(g.type - 1)];
    t.reflectance = g.colour;
    t.transmittance = g.colour * kLeafTransmittanceRatio;
    t.density_per_m2 = g.density_per_m2;
    t.blade_length = g.blade_length;
    t.blade_width = g.blade_width;
    t.curvature = g.curvature;
    defined[static_cast<std::size_t>(g.type - 1)] = true;
  }
  const std::array<double, 4> b = map.bounds();
  cover.tile = kGrassTile;
  cover.corner = Vec3{b[0], b[1], 0.0} - Vec3{scene.origin.x, scene.origin.y, 0.0};
  cover.cols = static_cast<int>(std::ceil((b[2] - b[0]) / kGrassTile));
  cover.rows = static_cast<int>(std::ceil((b[3] - b[1]) / kGrassTile));
  const auto tiles = static_cast<std::size_t>(cover.cols) * static_cast<std::size_t>(cover.rows);
  cover.type.assign(tiles, 0);
  cover.height.assign(tiles, 0.0f);
  cover.normal.assign(tiles, Vec3f{0.0f, 0.0f, 1.0f});
  tbb::parallel_for(0, cover.rows, [&](int r) {
    for (int c = 0; c < cover.cols; ++c) {
      const double x = b[0] + (c + 0.5) * kGrassTile, y = b[1] + (r + 0.5) * kGrassTile;
      const auto cell = map.cell_at(x, y);
      const auto z = grid.height(x, y);
      if (!cell || !z || cell->grass_type() == 0 ||
          !defined[static_cast<std::size_t>(cell->grass_type() - 1)])
        continue;
      const std::size_t k = static_cast<std::size_t>(r) * cover.cols + c;
      cover.type[k] = static_cast<std::uint8_t>(cell->grass_type());
      cover.height[k] = static_cast<float>(*z - scene.origin.z);
      cover.normal[k] = Vec3f(*grid.normal(x, y));
    }
  });
}

// A ground feature map: a raster whose non-zero cells carry one material.
struct MaterialRaster {
  std::optional<terrain::ElevationGrid> grid;
  bool covers(double x, double y) const {
    if (!grid) return false;
    const terrain::GeoTransform& t = grid->transform();
    const double c = (x - t.origin_x) / t.cell_size_x, r = (t.origin_y - y) / t.cell_size_y;
    if (!(c >= 0 && r >= 0 && c < grid->cols() && r < grid->rows())) return false;
    const float v = grid->at(static_cast<int>(c), static_cast<int>(r));
    return !std::isnan(v) && v != 0.0f;
  }
};

MaterialRaster material_raster(const std::string& path) {
  if (path.empty()) return {};
  return {terrain::load_elevation(path)};
}

// Ground materials per triangle, by priority: road, water, rock, soil, then the grass tint.
void add_ground_materials(const Scenario& s, const featuremaps::VegetationMap* map,
                          const terrain::ElevationGrid& grid, renderer::Scene& scene) {
  const FeatureMapSettings& f = *s.featuremaps;
  const std::array<MaterialRaster, 4> rasters{material_raster(f.road), material_raster(f.water),
                                              material_raster(f.rock), material_raster(f.soil)};
  renderer::Ground& ground = scene.ground;
  // Ids: 1 road, 2 water, 3 rock, 4 soil, 5-7 ground under grass types 1-3.
  ground.materials = {{s.ground.road, false},
                      {s.ground.water, true},
                      {s.ground.rock, false},
                      {s.ground.soil, false}};
  for (int t = 0; t < 3; ++t) {
    // Seen from afar grass is its colour; the ground under it takes a darker shade of it.
    ground.materials.push_back(
        {scene.grass.types[static_cast<std::size_t>(t)].reflectance * 0.9f, false});
  }
  const bool any_raster = !f.road.empty() || !f.water.empty() || !f.rock.empty() || !f.soil.empty();
  if (!any_raster && (map == nullptr || s.grass.empty())) return;
  const terrain::GroundMesh& mesh = ground.mesh;
  ground.triangle_material.assign(mesh.triangle_count(), 0);
  tbb::parallel_for(std::size_t{0}, mesh.triangle_count(), [&](std::size_t t) {
    const Vec3f a = mesh.vertices[mesh.indices[3 * t]], b = mesh.vertices[mesh.indices[3 * t + 1]],
                c = mesh.vertices[mesh.indices[3 * t + 2]];
    const Vec3 centre = Vec3((a + b + c) / 3.0f) + scene.origin;
    for (std::size_t m = 0; m < rasters.size(); ++m) {
      if (rasters[m].covers(centre.x, centre.y)) {
        ground.triangle_material[t] = static_cast<std::uint8_t>(m + 1);
        return;
      }
    }
    if (map != nullptr) {
      const auto cell = map->cell_at(centre.x, centre.y);
      if (cell && cell->grass_type() > 0) {
        for (const GrassSettings& g : s.grass) {
          if (g.type == cell->grass_type())
            ground.triangle_material[t] = static_cast<std::uint8_t>(4 + g.type);
        }
      }
    }
  });
  (void)grid;
}

}  // namespace

Vec3 sun_direction(double elevation_deg, double azimuth_deg) {
  const double el = elevation_deg * std::numbers::pi / 180.0;
  const double az = azimuth_deg * std::numbers::pi / 180.0;
  return {std::sin(az) * std::cos(el), std::cos(az) * std::cos(el), std::sin(el)};
}

renderer::Scene build_scene(const Scenario& scenario, double time) {
  const terrain::ElevationGrid grid =
      terrain::load_elevation(scenario.terrain.elevation, scenario.terrain.dem);
  renderer::Scene scene;
  scene.origin = grid.centre();
  scene.ground.mesh = terrain::build_ground_mesh(grid, scene.origin);
  scene.ground.albedo = scenario.terrain.albedo;
  scene.sun.direction = sun_direction(scenario.sun.elevation_deg, scenario.sun.azimuth_deg);
  scene.sky.physical = scenario.sky.physical;
  scene.sky.turbidity = scenario.sky.turbidity;
  if (scenario.sun.irradiance) {
    scene.sun.irradiance = *scenario.sun.irradiance;
  } else if (scenario.sky.physical) {
    scene.sun.irradiance =
        renderer::sun_irradiance(scenario.sun.elevation_deg, scenario.sky.turbidity);
  }
  scene.haze.enabled = scenario.haze.enabled;
  scene.haze.visibility = scenario.haze.visibility;
  scene.haze.scale_height = scenario.haze.scale_height;
  scene.haze.albedo = scenario.haze.colour;
  scene.haze.asymmetry = scenario.haze.asymmetry;
  scene.haze.base_height =
      grid.min_height() - scene.origin.z;  // the visibility holds at the lowest ground
  for (const ViewSettings& v : scenario.views) {
    scene.views.push_back({v.name, v.position - scene.origin, v.target - scene.origin, v.fov_y_deg,
                           v.width, v.height});
  }
  scene.settings.spp = scenario.render.spp;
  scene.settings.seed = scenario.render.seed;
  scene.settings.max_bounces = scenario.render.max_bounces;
  scene.settings.exposure_ev = scenario.render.exposure_ev;
  scene.settings.degradation = scenario.render.degradation;
  if (scenario.featuremaps) {
    const FeatureMapSettings& f = *scenario.featuremaps;
    std::optional<featuremaps::VegetationMap> map;
    if (!f.vegetation.empty() || !f.classes.empty()) {
      map = vegetation_map(f, scenario.render.seed);
      check_overlap(*map, grid, f.vegetation.empty() ? f.classes : f.vegetation);
      if (const std::size_t multi = map->multi_species_cells(); multi > 0) {
        spdlog::warn("{} feature-map cells select several tree species; the lowest bit wins",
                     multi);
      }
    } else if (!scenario.species.empty() || !scenario.grass.empty()) {
      throw InputError(scenario.source +
                       ": [[species]] and [[grass]] need [featuremaps] vegetation or classes");
    }
    if (map && !scenario.species.empty()) add_trees(scenario, *map, grid, time, scene);
    if (map && !scenario.grass.empty()) add_grass(scenario, *map, grid, scene);
    add_ground_materials(scenario, map ? &*map : nullptr, grid, scene);
  }
  return scene;
}

}  // namespace landsim::scenes
