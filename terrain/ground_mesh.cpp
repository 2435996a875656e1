#include "terrain/ground_mesh.h"

#include <algorithm>
#include <array>

namespace landsim::terrain {
namespace {

// Adds the triangles of the quad whose north-west corner is cell (c, r).
void add_quad(const ElevationGrid& g, int c, int r, std::vector<std::uint32_t>& out) {
  const auto id = [&](int cc, int rr) { return static_cast<std::uint32_t>(rr * g.cols() + cc); };
  // Corners counter-clockwise seen from above (x east, y north): SW, SE, NE, NW.
  const std::array<std::uint32_t, 4> v{id(c, r + 1), id(c + 1, r + 1), id(c + 1, r), id(c, r)};
  const std::array<bool, 4> ok{g.valid(c, r + 1), g.valid(c + 1, r + 1), g.valid(c + 1, r),
                               g.valid(c, r)};
  const int valid = ok[0] + ok[1] + ok[2] + ok[3];
  if (valid == 4) {
    out.insert(out.end(), {v[0], v[1], v[2], v[0], v[2], v[3]});
  } else if (valid == 3) {
    std::array<std::uint32_t, 3> tri{};
    int n = 0;
    for (int i = 0; i < 4; ++i) {
      if (ok[i]) tri[n++] = v[i];  // keeps the counter-clockwise order
    }
    out.insert(out.end(), tri.begin(), tri.end());
  }
}

}  // namespace

Vec3 grid_vertex_normal(const ElevationGrid& g, int c, int r) {
  if (!g.valid(c, r)) return {0.0, 0.0, 1.0};
  const auto h = [&](int cc, int rr) -> double {
    return g.valid(cc, rr) ? g.at(cc, rr) : g.at(c, r);
  };
  const int west = std::max(c - 1, 0), east = std::min(c + 1, g.cols() - 1);
  const int north = std::max(r - 1, 0), south = std::min(r + 1, g.rows() - 1);
  const double dx = (east - west) * g.transform().cell_size_x;
  const double dy = (south - north) * g.transform().cell_size_y;
  const double dh_dx = dx > 0.0 ? (h(east, r) - h(west, r)) / dx : 0.0;
  const double dh_dy = dy > 0.0 ? (h(c, north) - h(c, south)) / dy : 0.0;  // north is +y
  return normalize(Vec3{-dh_dx, -dh_dy, 1.0});
}

GroundMesh build_ground_mesh(const ElevationGrid& grid, const Vec3& origin) {
  GroundMesh mesh;
  mesh.vertices.reserve(static_cast<std::size_t>(grid.cols()) * grid.rows());
  mesh.normals.reserve(mesh.vertices.capacity());
  for (int r = 0; r < grid.rows(); ++r) {
    for (int c = 0; c < grid.cols(); ++c) {
      // Nodata vertices are never referenced; they sit at the origin height harmlessly.
      const double h = grid.valid(c, r) ? grid.at(c, r) : origin.z;
      const Vec3 p{grid.x_of_col(c), grid.y_of_row(r), h};
      mesh.vertices.push_back(Vec3f(p - origin));
      mesh.normals.push_back(Vec3f(grid_vertex_normal(grid, c, r)));
    }
  }
  for (int r = 0; r + 1 < grid.rows(); ++r) {
    for (int c = 0; c + 1 < grid.cols(); ++c) add_quad(grid, c, r, mesh.indices);
  }
  return mesh;
}

}  // namespace landsim::terrain
