#include "scenes/builder/detail/vegetation_input.h"

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

// How the warnings below name one kind of entry.
struct EntryWords {
  const char* table;        // "species"
  const char* key;          // "bit"
  const char* value;        // "species bit"
  const char* lost;         // what unclaimed cells get none of: "trees"
  const char* consequence;  // of an entry no cell selects: "it places no trees"
};

// One kind of entry (species bits or grass types) against the cells: values cells select
// that no entry defines, and entries no cell selects. `note(entry)` adds to its name.
template <typename Entry, typename ValueOf, typename Note>
void check_entries(const std::vector<std::size_t>& selecting, int first,
                   const std::vector<Entry>& entries, ValueOf value_of, Note note,
                   const EntryWords& w, const std::string& path) {
  for (int v = first; v < static_cast<int>(selecting.size()); ++v) {
    const std::size_t n = selecting[static_cast<std::size_t>(v)];
    const bool defined = std::any_of(entries.begin(), entries.end(),
                                     [&](const Entry& e) { return value_of(e) == v; });
    if (n > 0 && !defined)
      warn_input(fmt::format("{}: {} cells select {} {}, but no [[{}]] has {} = {}: they get no {}",
                             path, n, w.value, v, w.table, w.key, v, w.lost));
  }
  for (const Entry& e : entries)
    if (selecting[static_cast<std::size_t>(value_of(e))] == 0)
      warn_input(fmt::format("{}: [[{}]] {} {}{} is selected by no cell: {}", e.location, w.table,
                             w.key, value_of(e), note(e), w.consequence));
}

// Silent wrong scenes: cells selecting a species bit or grass type that no entry defines, and
// entries that no cell selects.
void check_use(const Scenario& s, const featuremaps::VegetationMap& map, const std::string& path) {
  std::vector<std::size_t> bits(featuremaps::kTreeBits, 0), grass(4, 0);
  for (int r = 0; r < map.rows(); ++r)
    for (int c = 0; c < map.cols(); ++c) {
      const featuremaps::VegetationCell v = map.at(c, r);
      for (int b = 0; b < featuremaps::kTreeBits; ++b)
        bits[static_cast<std::size_t>(b)] += v.has_tree_bit(b);
      ++grass[static_cast<std::size_t>(v.grass_type())];
    }
  check_entries(
      bits, 0, s.species, [](const SpeciesSettings& k) { return k.bit; },
      [](const SpeciesSettings& k) { return " (" + k.species.name + ")"; },
      EntryWords{"species", "bit", "species bit", "trees", "it places no trees"}, path);
  check_entries(
      grass, 1, s.grass, [](const GrassSettings& g) { return g.type; },
      [](const GrassSettings&) { return std::string(); },
      EntryWords{"grass", "type", "grass type", "grass", "it grows nowhere"}, path);
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
      spdlog::info("{} feature-map cells are mixed stands of several tree species", multi);
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
