#include "featuremaps/placement.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <unordered_map>

#include "core/counter_rng.h"
#include "core/input_error.h"

namespace landsim::featuremaps {
namespace {

// The candidate of one grid cell, or nothing when the cell's spot does not select the species.
bool candidate(const VegetationMap& map, const terrain::ElevationGrid& terrain,
               const SpeciesPlacement& sp, std::uint32_t species_index, double spacing, double x0,
               double y0, std::int64_t i, std::int64_t j, std::uint64_t seed, PlacedTree& out) {
  const std::uint64_t key =
      hash_combine(hash_combine(static_cast<std::uint64_t>(sp.bit), static_cast<std::uint64_t>(i)),
                   static_cast<std::uint64_t>(j));
  const CounterRng r(seed, key, 0);
  const double jitter = 0.5 * (spacing - sp.min_spacing);  // keeps neighbours min_spacing apart
  const double x =
      x0 + (static_cast<double>(i) + 0.5) * spacing + jitter * (2.0 * r.uniform(0) - 1.0);
  const double y =
      y0 + (static_cast<double>(j) + 0.5) * spacing + jitter * (2.0 * r.uniform(1) - 1.0);
  const auto cell = map.cell_at(x, y);
  if (!cell || !cell->has_tree_bit(sp.bit)) return false;
  const auto z = terrain.height(x, y);
  if (!z) return false;
  out.species = species_index;
  out.variant = std::min(static_cast<std::uint32_t>(r.uniform(2) * static_cast<float>(sp.variants)),
                         static_cast<std::uint32_t>(sp.variants - 1));
  out.x = x;
  out.y = y;
  out.z = *z;
  out.rotation = 2.0 * std::numbers::pi * r.uniform(3);
  out.scale = 1.0 + sp.scale_variation * (2.0 * r.uniform(4) - 1.0);
  return true;
}

// Trees in cells of several species compete for room: in species order, a tree that stands
// closer to an earlier species' kept tree than the larger of their two minimum spacings gives
// way. Cells of one species are left as placed (their trees meet only their own kind).
std::vector<PlacedTree> compete_in_mixed_stands(const VegetationMap& map,
                                                const std::vector<SpeciesPlacement>& species,
                                                std::vector<PlacedTree> all) {
  double reach = 0.0;
  for (const SpeciesPlacement& sp : species) reach = std::max(reach, sp.min_spacing);
  if (!(reach > 0.0)) return all;
  const auto mixed = [&](const PlacedTree& t) {
    const auto cell = map.cell_at(t.x, t.y);
    return cell && cell->tree_bit_count() > 1;
  };
  // Kept trees of mixed cells, by grid square of side `reach`.
  std::unordered_map<std::uint64_t, std::vector<std::size_t>> near;
  const auto square = [&](double x, double y, int dx, int dy) {
    const auto i = static_cast<std::int64_t>(std::floor(x / reach)) + dx;
    const auto j = static_cast<std::int64_t>(std::floor(y / reach)) + dy;
    return (static_cast<std::uint64_t>(i) << 32) ^ static_cast<std::uint64_t>(j & 0xffffffff);
  };
  std::vector<PlacedTree> kept;
  kept.reserve(all.size());
  for (const PlacedTree& t : all) {  // species by species: earlier species first
    if (!mixed(t)) {
      kept.push_back(t);
      continue;
    }
    bool room = true;
    for (int dx = -1; dx <= 1 && room; ++dx)
      for (int dy = -1; dy <= 1 && room; ++dy) {
        const auto it = near.find(square(t.x, t.y, dx, dy));
        if (it == near.end()) continue;
        for (const std::size_t k : it->second) {
          const PlacedTree& o = kept[k];
          const double gap =
              std::max(species[t.species].min_spacing, species[o.species].min_spacing);
          if (o.species != t.species && std::hypot(o.x - t.x, o.y - t.y) < gap) room = false;
        }
      }
    if (!room) continue;
    near[square(t.x, t.y, 0, 0)].push_back(kept.size());
    kept.push_back(t);
  }
  return kept;
}

}  // namespace

double grid_spacing(double density_per_ha) { return std::sqrt(10000.0 / density_per_ha); }

std::vector<PlacedTree> place_trees(const VegetationMap& map, const terrain::ElevationGrid& terrain,
                                    const std::vector<SpeciesPlacement>& species,
                                    std::uint64_t seed) {
  const std::array<double, 4> b = map.bounds();
  std::vector<PlacedTree> all;
  for (std::size_t s = 0; s < species.size(); ++s) {
    const SpeciesPlacement& sp = species[s];
    const double spacing = grid_spacing(sp.density_per_ha);
    if (sp.min_spacing > spacing) {
      throw InputError("species bit " + std::to_string(sp.bit) + ": min_spacing " +
                       std::to_string(sp.min_spacing) + " m exceeds the grid spacing " +
                       std::to_string(spacing) + " m of density " +
                       std::to_string(sp.density_per_ha) + " per hectare");
    }
    const auto cols = static_cast<std::int64_t>(std::ceil((b[2] - b[0]) / spacing));
    const auto rows = static_cast<std::int64_t>(std::ceil((b[3] - b[1]) / spacing));
    std::vector<std::vector<PlacedTree>> per_row(static_cast<std::size_t>(rows));
    tbb::parallel_for(tbb::blocked_range<std::int64_t>(0, rows),
                      [&](const tbb::blocked_range<std::int64_t>& range) {
                        for (std::int64_t j = range.begin(); j != range.end(); ++j) {
                          std::vector<PlacedTree>& row = per_row[static_cast<std::size_t>(j)];
                          PlacedTree t;
                          for (std::int64_t i = 0; i < cols; ++i) {
                            if (candidate(map, terrain, sp, static_cast<std::uint32_t>(s), spacing,
                                          b[0], b[1], i, j, seed, t))
                              row.push_back(t);
                          }
                        }
                      });
    // Concatenated in row order: the result does not depend on how rows were scheduled.
    for (std::vector<PlacedTree>& row : per_row) all.insert(all.end(), row.begin(), row.end());
  }
  return compete_in_mixed_stands(map, species, std::move(all));
}

}  // namespace landsim::featuremaps
