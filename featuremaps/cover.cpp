#include "featuremaps/cover.h"

#include <algorithm>
#include <cmath>

#include "core/value_noise.h"

namespace landsim::featuremaps {
namespace {

// The combined map's cells are capped: a fine feature map over a large terrain is resampled
// no finer than this many cells (2 bytes each).
constexpr std::size_t kMaxCells = std::size_t{1} << 26;
// Patches: smooth value noise at these wavelengths (metres), the first weighted most.
constexpr double kPatchScales[] = {400.0, 120.0};

double patch_field(double x, double y, std::uint64_t seed) {
  return 0.7 * value_noise(x, y, kPatchScales[0], seed) +
         0.3 * value_noise(x, y, kPatchScales[1], mix64(seed));
}

struct Grid {
  int cols = 0, rows = 0;
  terrain::GeoTransform transform;
  double x(int c) const { return transform.origin_x + (c + 0.5) * transform.cell_size_x; }
  double y(int r) const { return transform.origin_y - (r + 0.5) * transform.cell_size_y; }
};

// The terrain's extent at the finer of the two cell sizes, within the cell cap.
Grid combined_grid(const std::optional<VegetationMap>& features,
                   const terrain::ElevationGrid& terrain) {
  const terrain::GeoTransform& t = terrain.transform();
  const double width = terrain.cols() * t.cell_size_x, height = terrain.rows() * t.cell_size_y;
  double cell = std::min(t.cell_size_x, t.cell_size_y);
  if (features)
    cell = std::min({cell, features->transform().cell_size_x, features->transform().cell_size_y});
  const double area_cells = (width / cell) * (height / cell);
  if (area_cells > static_cast<double>(kMaxCells))
    cell *= std::sqrt(area_cells / static_cast<double>(kMaxCells));
  Grid g;
  g.cols = std::max(1, static_cast<int>(std::ceil(width / cell)));
  g.rows = std::max(1, static_cast<int>(std::ceil(height / cell)));
  g.transform = {t.origin_x, t.origin_y, width / g.cols, height / g.rows};
  return g;
}

// For each fraction request, its band [lo, hi) of the patch field's values over the grid: the
// quantiles, so that each takes its share of the terrain.
std::vector<std::array<double, 2>> fraction_bands(const Grid& g,
                                                  const std::vector<CoverRequest>& requests,
                                                  std::uint64_t seed) {
  std::vector<std::array<double, 2>> bands(requests.size(), {0.0, 0.0});
  const bool any = std::any_of(requests.begin(), requests.end(), [](const CoverRequest& r) {
    return r.cover.kind == Cover::Kind::fraction;
  });
  if (!any) return bands;
  std::vector<double> values;
  values.reserve(static_cast<std::size_t>(g.cols) * static_cast<std::size_t>(g.rows));
  for (int r = 0; r < g.rows; ++r)
    for (int c = 0; c < g.cols; ++c) values.push_back(patch_field(g.x(c), g.y(r), seed));
  std::sort(values.begin(), values.end());
  const auto quantile = [&](double q) {
    if (q >= 1.0) return 2.0;  // above every value: the band reaches the end
    return values[std::min(values.size() - 1,
                           static_cast<std::size_t>(q * static_cast<double>(values.size())))];
  };
  double taken = 0.0;
  for (std::size_t i = 0; i < requests.size(); ++i) {
    if (requests[i].cover.kind != Cover::Kind::fraction) continue;
    const double start = taken;
    taken = std::min(1.0, taken + requests[i].cover.fraction);
    bands[i] = {start <= 0.0 ? -1.0 : quantile(start), quantile(taken)};
  }
  return bands;
}

bool covers(const Cover& cover, const std::array<double, 2>& band, double x, double y,
            double patch) {
  switch (cover.kind) {
    case Cover::Kind::everywhere:
      return true;
    case Cover::Kind::fraction:
      return patch >= band[0] && patch < band[1];
    case Cover::Kind::polygon:
      return polygon_contains(cover.polygon, x, y);
  }
  return false;
}

}  // namespace

bool polygon_contains(const std::vector<std::array<double, 2>>& p, double x, double y) {
  if (p.size() < 3) return false;
  bool inside = false;
  for (std::size_t i = 0, j = p.size() - 1; i < p.size(); j = i++) {
    const double xi = p[i][0], yi = p[i][1], xj = p[j][0], yj = p[j][1];
    if ((yi > y) != (yj > y) && x < (xj - xi) * (y - yi) / (yj - yi) + xi) inside = !inside;
  }
  return inside;
}

std::optional<VegetationMap> covered_map(const std::optional<VegetationMap>& features,
                                         const terrain::ElevationGrid& terrain,
                                         const std::vector<CoverRequest>& trees,
                                         const std::vector<CoverRequest>& grass,
                                         std::uint64_t seed) {
  if (trees.empty() && grass.empty()) return features;
  const Grid g = combined_grid(features, terrain);
  const std::uint64_t tree_seed = mix64(seed ^ 0x7472656573ULL),
                      grass_seed = mix64(seed ^ 0x6772617373ULL);
  const auto tree_bands = fraction_bands(g, trees, tree_seed);
  const auto grass_bands = fraction_bands(g, grass, grass_seed);
  std::vector<std::uint16_t> cells(static_cast<std::size_t>(g.cols) *
                                   static_cast<std::size_t>(g.rows));
  for (int r = 0; r < g.rows; ++r) {
    for (int c = 0; c < g.cols; ++c) {
      const double x = g.x(c), y = g.y(r);
      std::uint16_t v = 0;
      if (features)
        if (const auto cell = features->cell_at(x, y)) v = cell->raw;
      if ((v & kTreeMask) == 0) {
        const double patch = patch_field(x, y, tree_seed);
        for (std::size_t i = 0; i < trees.size(); ++i)
          if (covers(trees[i].cover, tree_bands[i], x, y, patch)) {
            v = static_cast<std::uint16_t>(v | (1u << trees[i].value));
            break;
          }
      }
      if ((v >> kTreeBits) == 0) {
        const double patch = patch_field(x, y, grass_seed);
        for (std::size_t i = 0; i < grass.size(); ++i)
          if (covers(grass[i].cover, grass_bands[i], x, y, patch)) {
            v = static_cast<std::uint16_t>(v | (grass[i].value << kTreeBits));
            break;
          }
      }
      cells[static_cast<std::size_t>(r) * static_cast<std::size_t>(g.cols) +
            static_cast<std::size_t>(c)] = v;
    }
  }
  return VegetationMap(g.cols, g.rows, g.transform, std::move(cells));
}

}  // namespace landsim::featuremaps
