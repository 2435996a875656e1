#include "scenes/detail/grass_cover.h"

#include <tbb/parallel_for.h>

#include <cmath>

namespace landsim::scenes::detail {

renderer::GrassCover grass_cover(const Scenario& s, const featuremaps::VegetationMap& map,
                                 const terrain::ElevationGrid& grid, const Vec3& origin) {
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
      const double x = b[0] + (c + 0.5) * kGrassTile, y = b[1] + (r + 0.5) * kGrassTile;
      const auto cell = map.cell_at(x, y);
      const auto z = grid.height(x, y);
      if (!cell || !z || cell->grass_type() == 0 ||
          !defined[static_cast<std::size_t>(cell->grass_type() - 1)])
        continue;
      const std::size_t k = static_cast<std::size_t>(r) * cover.cols + c;
      cover.type[k] = static_cast<std::uint8_t>(cell->grass_type());
      cover.height[k] = static_cast<float>(*z - origin.z);
      cover.normal[k] = Vec3f(*grid.normal(x, y));
    }
  });
  return cover;
}

}  // namespace landsim::scenes::detail
