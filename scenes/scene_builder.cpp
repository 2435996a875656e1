#include "scenes/scene_builder.h"

#include <spdlog/spdlog.h>
#include <tbb/parallel_for.h>

#include <cmath>
#include <map>
#include <numbers>

#include "core/counter_rng.h"
#include "featuremaps/class_mapping.h"
#include "featuremaps/placement.h"
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
                                       std::uint32_t variant, std::uint64_t seed) {
  renderer::TreePrototype p;
  const std::uint64_t vs = variant_seed(seed, sp.bit, variant);
  p.geometry = trees::generate(sp.species, {vs}).geometry;
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
  p.leaf_transmittance = p.leaf_reflectance * kLeafTransmittanceRatio;
  return p;
}

void add_trees(const Scenario& s, const terrain::ElevationGrid& grid, renderer::Scene& scene) {
  const std::uint64_t seed = s.render.seed;
  const featuremaps::VegetationMap map = vegetation_map(*s.featuremaps, seed);
  if (const std::size_t multi = map.multi_species_cells(); multi > 0) {
    spdlog::warn("{} feature-map cells select several tree species; the lowest bit wins", multi);
  }
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
  scene.prototypes.resize(keys.size());
  tbb::parallel_for(std::size_t{0}, keys.size(), [&](std::size_t i) {
    const auto [species, variant] = keys[i];
    scene.prototypes[i] = make_prototype(s.species[species], species, variant, seed);
  });
  scene.instances.reserve(placed.size());
  for (const featuremaps::PlacedTree& t : placed) {
    scene.instances.push_back({prototype_of.at({t.species, t.variant}),
                               Vec3{t.x, t.y, t.z} - scene.origin, t.rotation, t.scale});
  }
  spdlog::info("{} trees of {} variants", scene.instances.size(), scene.prototypes.size());
}

}  // namespace

Vec3 sun_direction(double elevation_deg, double azimuth_deg) {
  const double el = elevation_deg * std::numbers::pi / 180.0;
  const double az = azimuth_deg * std::numbers::pi / 180.0;
  return {std::sin(az) * std::cos(el), std::cos(az) * std::cos(el), std::sin(el)};
}

renderer::Scene build_scene(const Scenario& scenario) {
  const terrain::ElevationGrid grid =
      terrain::load_elevation(scenario.terrain.elevation, scenario.terrain.dem);
  renderer::Scene scene;
  scene.origin = grid.centre();
  scene.ground.mesh = terrain::build_ground_mesh(grid, scene.origin);
  scene.ground.albedo = scenario.terrain.albedo;
  scene.sun.direction = sun_direction(scenario.sun.elevation_deg, scenario.sun.azimuth_deg);
  scene.sun.irradiance = scenario.sun.irradiance;
  for (const ViewSettings& v : scenario.views) {
    scene.views.push_back({v.name, v.position - scene.origin, v.target - scene.origin, v.fov_y_deg,
                           v.width, v.height});
  }
  scene.settings.spp = scenario.render.spp;
  scene.settings.seed = scenario.render.seed;
  scene.settings.max_bounces = scenario.render.max_bounces;
  scene.settings.exposure_ev = scenario.render.exposure_ev;
  if (scenario.featuremaps && !scenario.species.empty()) add_trees(scenario, grid, scene);
  return scene;
}

}  // namespace landsim::scenes
