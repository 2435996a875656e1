#include "scenes/detail/vegetation_input.h"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <array>

#include "core/input_error.h"
#include "core/input_warnings.h"
#include "featuremaps/class_mapping.h"

namespace landsim::scenes::detail {
namespace {

featuremaps::VegetationMap vegetation_map(const FeatureMapSettings& f, std::uint64_t seed) {
  if (!f.vegetation.empty()) return featuremaps::load_vegetation_map(f.vegetation, f.placement);
  terrain::DemOptions options;
  options.cell_size = f.placement.cell_size;
  options.origin = f.placement.origin;
  const terrain::ElevationGrid classes = terrain::load_elevation(f.classes, options);
  return featuremaps::build_vegetation_map(classes, featuremaps::load_class_mapping(f.class_map),
                                           seed);
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
        "{}: feature map ({:.1f}, {:.1f})-({:.1f}, {:.1f}) does not overlap the elevation "
        "grid's raster extent ({:.1f}, {:.1f})-({:.1f}, {:.1f}) (west, south)-(east, north); "
        "check its georeferencing or [featuremaps] origin",
        path, b[0], b[1], b[2], b[3], west, south, east, north));
  }
}

// Silent wrong scenes: cells selecting a species bit or grass type that no entry defines, and
// entries that no cell selects.
void check_use(const Scenario& s, const featuremaps::VegetationMap& map, const std::string& path) {
  std::array<std::size_t, featuremaps::kTreeBits> bits{};
  std::array<std::size_t, 4> grass{};
  for (int r = 0; r < map.rows(); ++r)
    for (int c = 0; c < map.cols(); ++c) {
      const featuremaps::VegetationCell v = map.at(c, r);
      if (const auto b = v.species_bit()) ++bits[static_cast<std::size_t>(*b)];
      ++grass[static_cast<std::size_t>(v.grass_type())];
    }
  for (int b = 0; b < featuremaps::kTreeBits; ++b) {
    const bool defined = std::any_of(s.species.begin(), s.species.end(),
                                     [&](const SpeciesSettings& k) { return k.bit == b; });
    if (bits[static_cast<std::size_t>(b)] > 0 && !defined)
      warn_input(
          fmt::format("{}: {} cells select species bit {}, but no [[species]] has bit = {}: "
                      "they get no trees",
                      path, bits[static_cast<std::size_t>(b)], b, b));
  }
  for (const SpeciesSettings& k : s.species)
    if (bits[static_cast<std::size_t>(k.bit)] == 0)
      warn_input(
          fmt::format("{}: [[species]] bit {} ({}) is selected by no cell: it places no "
                      "trees",
                      k.location, k.bit, k.species.name));
  for (int t = 1; t <= 3; ++t) {
    const bool defined = std::any_of(s.grass.begin(), s.grass.end(),
                                     [&](const GrassSettings& g) { return g.type == t; });
    if (grass[static_cast<std::size_t>(t)] > 0 && !defined)
      warn_input(
          fmt::format("{}: {} cells select grass type {}, but no [[grass]] has type = {}: "
                      "they get no grass",
                      path, grass[static_cast<std::size_t>(t)], t, t));
  }
  for (const GrassSettings& g : s.grass)
    if (grass[static_cast<std::size_t>(g.type)] == 0)
      warn_input(fmt::format("{}: [[grass]] type {} is selected by no cell: it grows nowhere",
                             g.location, g.type));
}

}  // namespace

std::optional<featuremaps::VegetationMap> scene_vegetation(const Scenario& s,
                                                           const terrain::ElevationGrid& grid) {
  std::optional<featuremaps::VegetationMap> map;
  if (s.featuremaps && (!s.featuremaps->vegetation.empty() || !s.featuremaps->classes.empty())) {
    const FeatureMapSettings& f = *s.featuremaps;
    map = vegetation_map(f, s.render.seed);
    check_overlap(*map, grid, f.vegetation.empty() ? f.classes : f.vegetation);
    if (const std::size_t multi = map->multi_species_cells(); multi > 0)
      spdlog::warn("{} feature-map cells select several tree species; the lowest bit wins", multi);
  }
  // Covers fill in where the feature map (if any) selects nothing, in file order.
  std::vector<featuremaps::CoverRequest> trees, grass;
  for (const SpeciesSettings& k : s.species)
    if (k.cover) trees.push_back({k.bit, *k.cover});
  for (const GrassSettings& g : s.grass)
    if (g.cover) grass.push_back({g.type, *g.cover});
  std::optional<featuremaps::VegetationMap> covered =
      featuremaps::covered_map(map, grid, trees, grass, s.render.seed);
  if (covered) {
    // Name what selected the cells: the vegetation raster, or the class mapping.
    std::string path = s.source;
    if (map)
      path =
          s.featuremaps->vegetation.empty() ? s.featuremaps->class_map : s.featuremaps->vegetation;
    check_use(s, *covered, path);
  }
  return covered;
}

}  // namespace landsim::scenes::detail
