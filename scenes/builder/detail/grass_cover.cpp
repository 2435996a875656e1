#include "scenes/builder/detail/grass_cover.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

namespace landsim::scenes::detail {
namespace {

// The map's grass types cell by cell (south row first), types no [[grass]] defines and
// blocked cells left out.
renderer::GrassMask grass_mask(const featuremaps::VegetationMap& map, const Vec3& origin,
                               const std::array<bool, 3>& defined, const GrassBlocked& blocked) {
  renderer::GrassMask mask;
  const terrain::GeoTransform& t = map.transform();
  const std::array<double, 4> b = map.bounds();
  mask.corner = Vec3{b[0] - origin.x, b[1] - origin.y, 0.0};
  mask.cell_x = t.cell_size_x;
  mask.cell_y = t.cell_size_y;
  mask.cols = map.cols();
  mask.rows = map.rows();
  mask.type.assign(static_cast<std::size_t>(mask.cols) * static_cast<std::size_t>(mask.rows), 0);
  tbb::parallel_for(0, map.rows(), [&](int r) {
    for (int c = 0; c < map.cols(); ++c) {
      const int type = map.at(c, r).grass_type();
      if (type == 0 || !defined[static_cast<std::size_t>(type - 1)]) continue;
      const double x = t.origin_x + (c + 0.5) * t.cell_size_x;
      const double y = t.origin_y - (r + 0.5) * t.cell_size_y;
      if (blocked && blocked(x, y)) continue;
      const std::size_t south_row = static_cast<std::size_t>(map.rows() - 1 - r);
      mask.type[south_row * static_cast<std::size_t>(mask.cols) + static_cast<std::size_t>(c)] =
          static_cast<std::uint8_t>(type);
    }
  });
  return mask;
}

// A tile's patch type: the mask's at its centre, else the first the tile's cells grant.
int tile_type(const renderer::GrassMask& m, double x0, double y0, double size) {
  const auto type_at = [&](int c, int r) {
    return m.type[static_cast<std::size_t>(r) * static_cast<std::size_t>(m.cols) +
                  static_cast<std::size_t>(c)];
  };
  const auto col = [&](double x) {
    return std::clamp(static_cast<int>(std::floor((x - m.corner.x) / m.cell_x)), 0, m.cols - 1);
  };
  const auto row = [&](double y) {
    return std::clamp(static_cast<int>(std::floor((y - m.corner.y) / m.cell_y)), 0, m.rows - 1);
  };
  if (const int centre = type_at(col(x0 + 0.5 * size), row(y0 + 0.5 * size)); centre != 0)
    return centre;
  for (int r = row(y0); r <= row(y0 + size); ++r)
    for (int c = col(x0); c <= col(x0 + size); ++c)
      if (type_at(c, r) != 0) return type_at(c, r);
  return 0;
}

}  // namespace

renderer::GrassCover grass_cover(const Scenario& s, const featuremaps::VegetationMap& map,
                                 const terrain::ElevationGrid& grid, const Vec3& origin,
                                 const GrassBlocked& blocked) {
  renderer::GrassCover cover;
  std::array<bool, 3> defined{};
  for (const GrassSettings& g : s.grass) {
    renderer::GrassType& t = cover.types[static_cast<std::size_t>(g.type - 1)];
    t.reflectance = g.colour;
    t.transmittance = g.colour * renderer::kLeafTransmittanceRatio;
    t.density_per_m2 = g.density_per_m2;
    t.blade_length = g.blade_length;
    t.blade_width = g.blade_width;
    t.curvature = g.curvature;
    defined[static_cast<std::size_t>(g.type - 1)] = true;
  }
  cover.mask = grass_mask(map, origin, defined, blocked);
  const std::array<double, 4> b = map.bounds();
  cover.tile = kGrassTile;
  cover.corner = Vec3{b[0], b[1], 0.0} - Vec3{origin.x, origin.y, 0.0};
  cover.cols = static_cast<int>(std::ceil((b[2] - b[0]) / kGrassTile));
  cover.rows = static_cast<int>(std::ceil((b[3] - b[1]) / kGrassTile));
  const auto tiles = static_cast<std::size_t>(cover.cols) * static_cast<std::size_t>(cover.rows);
  cover.type.assign(tiles, 0);
  cover.height.assign(tiles, 0.0f);
  cover.normal.assign(tiles, Vec3f{0.0f, 0.0f, 1.0f});
  tbb::parallel_for(0, cover.rows, [&](int r) {
    for (int c = 0; c < cover.cols; ++c) {
      const double x0 = cover.corner.x + c * kGrassTile, y0 = cover.corner.y + r * kGrassTile;
      const int type = tile_type(cover.mask, x0, y0, kGrassTile);
      const double x = b[0] + (c + 0.5) * kGrassTile, y = b[1] + (r + 0.5) * kGrassTile;
      const auto z = grid.height(x, y);
      if (type == 0 || !z) continue;
      const std::size_t k = static_cast<std::size_t>(r) * cover.cols + c;
      cover.type[k] = static_cast<std::uint8_t>(type);
      cover.height[k] = static_cast<float>(*z - origin.z);
      cover.normal[k] = Vec3f(*grid.normal(x, y));
    }
  });
  return cover;
}

}  // namespace landsim::scenes::detail
