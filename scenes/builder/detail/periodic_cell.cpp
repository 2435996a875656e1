#include "scenes/builder/detail/periodic_cell.h"

#include <algorithm>
#include <array>

namespace landsim::scenes::detail {
namespace {

// An instance's box in the scene frame (rotation about z taken as its circle).
std::array<Vec3, 2> instance_box(const renderer::Scene& scene, const renderer::TreeInstance& t) {
  const auto b = scene.prototypes[t.prototype].geometry.bounds();
  const double reach =
      t.scale * std::max({std::abs(b[0].x), std::abs(b[0].y), std::abs(b[1].x), std::abs(b[1].y)});
  const double radius = t.rotation == 0.0 ? 0.0 : reach * 1.4142135623730951;
  const Vec3 lo =
      t.rotation == 0.0 ? Vec3(b[0]) * t.scale : Vec3{-radius, -radius, b[0].z * t.scale};
  const Vec3 hi = t.rotation == 0.0 ? Vec3(b[1]) * t.scale : Vec3{radius, radius, b[1].z * t.scale};
  return {t.position + lo, t.position + hi};
}

}  // namespace

void make_periodic(const terrain::ElevationGrid& grid, renderer::Scene& scene) {
  renderer::PeriodicCell cell;
  cell.x0 = grid.x_of_col(0) - scene.origin.x;
  cell.x1 = grid.x_of_col(grid.cols() - 1) - scene.origin.x;
  cell.y0 = grid.y_of_row(grid.rows() - 1) - scene.origin.y;
  cell.y1 = grid.y_of_row(0) - scene.origin.y;
  double top = -1e30;
  for (const Vec3f& v : scene.ground.mesh.vertices) top = std::max(top, static_cast<double>(v.z));
  const double wx = cell.x1 - cell.x0, wy = cell.y1 - cell.y0;
  const std::size_t drawn = scene.instances.size();
  for (std::size_t i = 0; i < drawn; ++i) {
    const auto [lo, hi] = instance_box(scene, scene.instances[i]);
    top = std::max(top, hi.z);
    // Every shift by a period whose copy reaches into the cell.
    for (int sx = -1; sx <= 1; ++sx)
      for (int sy = -1; sy <= 1; ++sy) {
        if (sx == 0 && sy == 0) continue;
        const double dx = sx * wx, dy = sy * wy;
        if (hi.x + dx <= cell.x0 || lo.x + dx >= cell.x1 || hi.y + dy <= cell.y0 ||
            lo.y + dy >= cell.y1)
          continue;
        renderer::TreeInstance copy = scene.instances[i];
        copy.position += Vec3{dx, dy, 0.0};
        scene.instances.push_back(copy);
      }
  }
  cell.top = top + 1e-3;
  scene.periodic = cell;
  scene.ground.plain = false;
}

}  // namespace landsim::scenes::detail
