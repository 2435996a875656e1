#include "terrain/ground_mesh.h"

#include <algorithm>
#include <array>

namespace landsim::terrain {
namespace {

bool inside_and_valid(const ElevationGrid& g, int c, int r) {
  return c >= 0 && r >= 0 && c < g.cols() && r < g.rows() && g.valid(c, r);
}

std::uint32_t vertex_id(const ElevationGrid& g, int c, int r) {
  return static_cast<std::uint32_t>(r * g.cols() + c);
}

// The quad between cell centres (c, r) (its north-west corner) and (c + 1, r + 1) where some
// of its four cells lack data (nodata, or beyond the grid): the part of it that lies in the
// valid cells' own squares, so that every cell with data is drawn whole and no cell without
// (docs/GROUND.md "Nodata"). A fan from the quad's centre (at the mean of its valid cells):
// over a side between two valid cells the side itself, the edge the whole quad beside it has
// (no T-junction, no crack); over a side from a valid cell to one without, the half to the
// side's middle, level with the valid cell (its data reaches its edge flat).
void add_fan(const ElevationGrid& g, const Vec3& origin, int c, int r, GroundMesh& mesh) {
  // Counter-clockwise seen from above (x east, y north): SW, SE, NE, NW.
  const std::array<std::array<int, 2>, 4> corner{{{c, r + 1}, {c + 1, r + 1}, {c + 1, r}, {c, r}}};
  std::array<bool, 4> ok{};
  double centre_h = 0.0;
  Vec3 centre_n{};
  for (int i = 0; i < 4; ++i) {
    const auto [cc, rr] = corner[static_cast<std::size_t>(i)];
    ok[static_cast<std::size_t>(i)] = inside_and_valid(g, cc, rr);
    if (!ok[static_cast<std::size_t>(i)]) continue;
    centre_h += g.at(cc, rr);
    centre_n += grid_vertex_normal(g, cc, rr);
  }
  const int valid = ok[0] + ok[1] + ok[2] + ok[3];
  if (valid == 0) return;
  const auto add_vertex = [&](const Vec3& p, const Vec3& n) {
    mesh.vertices.push_back(Vec3f(p - origin));
    mesh.normals.push_back(Vec3f(n));
    return static_cast<std::uint32_t>(mesh.vertices.size() - 1);
  };
  const double xm = 0.5 * (g.x_of_col(c) + g.x_of_col(c + 1));
  const double ym = 0.5 * (g.y_of_row(r) + g.y_of_row(r + 1));
  const std::uint32_t centre = add_vertex({xm, ym, centre_h / valid}, normalize(centre_n));
  for (std::size_t i = 0; i < 4; ++i) {
    const std::size_t j = (i + 1) % 4;
    if (!ok[i] && !ok[j]) continue;
    const auto [ci, ri] = corner[i];
    const auto [cj, rj] = corner[j];
    if (ok[i] && ok[j]) {
      mesh.indices.insert(mesh.indices.end(), {centre, vertex_id(g, ci, ri), vertex_id(g, cj, rj)});
      continue;
    }
    // The side's middle, level with the valid end.
    const auto [cv, rv] = ok[i] ? corner[i] : corner[j];
    const Vec3 middle{0.5 * (g.x_of_col(ci) + g.x_of_col(cj)),
                      0.5 * (g.y_of_row(ri) + g.y_of_row(rj)), g.at(cv, rv)};
    const std::uint32_t m = add_vertex(middle, grid_vertex_normal(g, cv, rv));
    if (ok[i])
      mesh.indices.insert(mesh.indices.end(), {centre, vertex_id(g, ci, ri), m});
    else
      mesh.indices.insert(mesh.indices.end(), {centre, m, vertex_id(g, cj, rj)});
  }
}

// The quad between cell centres (c, r) and (c + 1, r + 1), c and r from -1 (the grid's
// outer cells are drawn to its edge): two triangles where all four cells hold data, else
// the quarters of those that do.
void add_quad(const ElevationGrid& g, const Vec3& origin, int c, int r, GroundMesh& mesh) {
  const bool whole = inside_and_valid(g, c, r) && inside_and_valid(g, c + 1, r) &&
                     inside_and_valid(g, c, r + 1) && inside_and_valid(g, c + 1, r + 1);
  if (!whole) return add_fan(g, origin, c, r, mesh);
  // Corners counter-clockwise seen from above (x east, y north): SW, SE, NE, NW.
  const std::array<std::uint32_t, 4> v{vertex_id(g, c, r + 1), vertex_id(g, c + 1, r + 1),
                                       vertex_id(g, c + 1, r), vertex_id(g, c, r)};
  mesh.indices.insert(mesh.indices.end(), {v[0], v[1], v[2], v[0], v[2], v[3]});
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
      // Nodata vertices are never referenced; they sit at the origin height harmlessly. (The
      // quarters at the data's edges append their own vertices after these.)
      const double h = grid.valid(c, r) ? grid.at(c, r) : origin.z;
      const Vec3 p{grid.x_of_col(c), grid.y_of_row(r), h};
      mesh.vertices.push_back(Vec3f(p - origin));
      mesh.normals.push_back(Vec3f(grid_vertex_normal(grid, c, r)));
    }
  }
  for (int r = -1; r < grid.rows(); ++r) {
    for (int c = -1; c < grid.cols(); ++c) add_quad(grid, origin, c, r, mesh);
  }
  return mesh;
}

}  // namespace landsim::terrain
