#include "terrain/context_mesh.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <unordered_map>
#include <unordered_set>

#include "core/input_error.h"

namespace landsim::terrain {
namespace {

// Beyond this many quadtree cells the views ask for more detail than memory allows.
constexpr std::size_t kMaxCells = 20'000'000;

// A quadtree cell: its north-west lattice point and its level (it spans 2^level cells).
struct Cell {
  int level = 0;
  long col = 0, row = 0;
  long span() const { return 1L << level; }
};

class Quadtree {
 public:
  Quadtree(const TerrainField& field, const ContextMeshOptions& options)
      : field_(field), options_(options) {
    const ElevationGrid& g = field.grid();
    const GeoTransform& t = g.transform();
    const auto [west, south, east, north] = field.extent();
    col0_ = static_cast<long>(std::floor((west - t.origin_x) / t.cell_size_x - 0.5));
    row0_ = static_cast<long>(std::floor((t.origin_y - north) / t.cell_size_y - 0.5));
    const long cols =
        static_cast<long>(std::ceil((east - t.origin_x) / t.cell_size_x - 0.5)) - col0_;
    const long rows =
        static_cast<long>(std::ceil((t.origin_y - south) / t.cell_size_y - 0.5)) - row0_;
    while ((1L << root_level_) < std::max({cols, rows, 1L})) ++root_level_;
    cell_metres_ = std::max(t.cell_size_x, t.cell_size_y);
    subdivide();
  }

  const std::vector<Cell>& leaves() const { return leaves_; }
  // True when the cell of that level at that corner was split (it exists and is finer).
  bool split(int level, long col, long row) const {
    return col >= col0_ && row >= row0_ && internal_.count(key(level, col, row)) > 0;
  }
  long col0() const { return col0_; }
  long row0() const { return row0_; }

 private:
  std::uint64_t key(int level, long col, long row) const {
    return (static_cast<std::uint64_t>(level) << 58) |
           (static_cast<std::uint64_t>(col - col0_) << 29) |
           static_cast<std::uint64_t>(row - row0_);
  }

  // The cell's rectangle in grid coordinates: west, south, east, north.
  std::array<double, 4> bounds(const Cell& c) const {
    const ElevationGrid& g = field_.grid();
    return {
        g.x_of_col(static_cast<double>(c.col)), g.y_of_row(static_cast<double>(c.row + c.span())),
        g.x_of_col(static_cast<double>(c.col + c.span())), g.y_of_row(static_cast<double>(c.row))};
  }

  bool has_data(const std::array<double, 4>& b) const {
    const auto e = field_.extent();
    return b[0] < e[2] && b[2] > e[0] && b[1] < e[3] && b[3] > e[1];
  }

  bool wants_split(const Cell& c, const std::array<double, 4>& b) const {
    const ElevationGrid& g = field_.grid();
    // Near the grid, in lattice cells: the grid itself is level 0.
    const double dc =
        static_cast<double>(std::max({0L, -(c.col + c.span()), c.col - (g.cols() - 1)}));
    const double dr =
        static_cast<double>(std::max({0L, -(c.row + c.span()), c.row - (g.rows() - 1)}));
    if (std::hypot(dc, dr) < kGridReach * static_cast<double>(c.span())) return true;
    // Near a view, in metres, while the halves are no finer than the finest context cell.
    const double size = cell_metres_ * static_cast<double>(c.span());
    if (0.5 * size < field_.finest_context_cell()) return false;
    for (const auto& v : options_.views) {
      const double dx = std::max({0.0, b[0] - v[0], v[0] - b[2]});
      const double dy = std::max({0.0, b[1] - v[1], v[1] - b[3]});
      if (std::hypot(dx, dy) < options_.range_factor * size) return true;
    }
    return false;
  }

  void subdivide() {
    std::vector<Cell> stack{{root_level_, col0_, row0_}};
    while (!stack.empty()) {
      const Cell c = stack.back();
      stack.pop_back();
      const std::array<double, 4> b = bounds(c);
      if (!has_data(b)) continue;
      if (c.level == 0 || !wants_split(c, b)) {
        leaves_.push_back(c);
        if (leaves_.size() > kMaxCells)
          throw InputError(fmt::format(
              "the context terrain would need more than {} mesh cells for these views (smaller "
              "or fewer views, or a coarser context grid)",
              kMaxCells));
        continue;
      }
      internal_.insert(key(c.level, c.col, c.row));
      const long h = c.span() / 2;
      for (const auto& [dc, dr] : {std::pair{0L, 0L}, {h, 0L}, {0L, h}, {h, h}})
        stack.push_back({c.level - 1, c.col + dc, c.row + dr});
    }
  }

  const TerrainField& field_;
  const ContextMeshOptions& options_;
  long col0_ = 0, row0_ = 0;
  int root_level_ = 0;
  double cell_metres_ = 1.0;
  std::vector<Cell> leaves_;
  std::unordered_set<std::uint64_t> internal_;
};

constexpr std::uint32_t kNoVertex = std::numeric_limits<std::uint32_t>::max();

// Vertices at lattice points, made once each; kNoVertex where no grid has data.
class Vertices {
 public:
  Vertices(const TerrainField& field, const Vec3& origin, long col0, long row0, ContextMesh& out)
      : field_(field), origin_(origin), col0_(col0), row0_(row0), out_(out) {}

  std::uint32_t at(long col, long row) {
    const std::uint64_t k =
        (static_cast<std::uint64_t>(col - col0_) << 32) | static_cast<std::uint64_t>(row - row0_);
    const auto [it, inserted] = index_.try_emplace(k, kNoVertex);
    if (!inserted) return it->second;
    const std::optional<double> h = field_.lattice_height(col, row);
    if (!h) return kNoVertex;
    const ElevationGrid& g = field_.grid();
    const Vec3 p{g.x_of_col(static_cast<double>(col)), g.y_of_row(static_cast<double>(row)), *h};
    it->second = static_cast<std::uint32_t>(out_.mesh.vertices.size());
    out_.mesh.vertices.push_back(Vec3f(p - origin_));
    own_.push_back(field_.from_grid(col, row));
    lattice_.push_back({col, row});
    return it->second;
  }

  bool own(std::uint32_t v) const { return own_[v]; }
  std::array<long, 2> lattice(std::uint32_t v) const { return lattice_[v]; }

 private:
  const TerrainField& field_;
  Vec3 origin_;
  long col0_, row0_;
  ContextMesh& out_;
  std::unordered_map<std::uint64_t, std::uint32_t> index_;
  std::vector<bool> own_;
  std::vector<std::array<long, 2>> lattice_;
};

class Triangulation {
 public:
  Triangulation(const Quadtree& tree, Vertices& vertices, ContextMesh& out)
      : tree_(tree), vertices_(vertices), out_(out) {}

  // Two triangles unless a neighbour is finer: then a fan that takes in its midpoints.
  void add(const Cell& c) {
    if (c.level > 0 && has_finer_neighbour(c)) {
      add_fan(c);
    } else {
      add_quad(c);
    }
  }

 private:
  void triangle(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    if (a == kNoVertex || b == kNoVertex || c == kNoVertex) return;
    out_.mesh.indices.insert(out_.mesh.indices.end(), {a, b, c});
    out_.from_context.push_back(!(vertices_.own(a) && vertices_.own(b) && vertices_.own(c)));
  }

  bool has_finer_neighbour(const Cell& c) const {
    const long s = c.span();
    return tree_.split(c.level, c.col, c.row + s) || tree_.split(c.level, c.col + s, c.row) ||
           tree_.split(c.level, c.col, c.row - s) || tree_.split(c.level, c.col - s, c.row);
  }

  // As the grid's own mesh (terrain/ground_mesh.cpp): SW-NE diagonal, one triangle when a
  // corner is missing.
  void add_quad(const Cell& c) {
    const long s = c.span();
    const std::array<std::uint32_t, 4> v{
        vertices_.at(c.col, c.row + s), vertices_.at(c.col + s, c.row + s),
        vertices_.at(c.col + s, c.row), vertices_.at(c.col, c.row)};  // SW, SE, NE, NW
    const int missing = static_cast<int>(std::count(v.begin(), v.end(), kNoVertex));
    if (missing == 0) {
      triangle(v[0], v[1], v[2]);
      triangle(v[0], v[2], v[3]);
    } else if (missing == 1) {
      std::array<std::uint32_t, 3> t{};
      int n = 0;
      for (std::uint32_t i : v)
        if (i != kNoVertex) t[static_cast<std::size_t>(n++)] = i;
      triangle(t[0], t[1], t[2]);
    }
  }

  // A fan from the centre through the corners, counter-clockwise seen from above, and through
  // the midpoint of each side whose neighbour is split (finer).
  void add_fan(const Cell& c) {
    const long s = c.span(), h = s / 2;
    const long w = c.col, e = c.col + s, n = c.row, so = c.row + s;
    std::array<std::uint32_t, 8> ring{};
    std::size_t count = 0;
    const auto corner = [&](long col, long row) { ring[count++] = vertices_.at(col, row); };
    const auto middle = [&](long col, long row, long ncol, long nrow) {
      if (tree_.split(c.level, ncol, nrow)) ring[count++] = vertices_.at(col, row);
    };
    corner(w, so);
    middle(w + h, so, w, so);  // south neighbour
    corner(e, so);
    middle(e, n + h, e, n);  // east neighbour
    corner(e, n);
    middle(w + h, n, w, n - s);  // north neighbour
    corner(w, n);
    middle(w, n + h, w - s, n);  // west neighbour
    const std::uint32_t centre = vertices_.at(w + h, n + h);
    for (std::size_t i = 0; i < count; ++i) triangle(centre, ring[i], ring[(i + 1) % count]);
  }

  const Quadtree& tree_;
  Vertices& vertices_;
  ContextMesh& out_;
};

// The grid's own samples keep the grid mesh's normals; the others average their triangles'.
void add_normals(const TerrainField& field, const Vertices& vertices, ContextMesh& out) {
  GroundMesh& m = out.mesh;
  std::vector<Vec3> sum(m.vertices.size());
  for (std::size_t t = 0; t < m.triangle_count(); ++t) {
    const std::uint32_t a = m.indices[3 * t], b = m.indices[3 * t + 1], c = m.indices[3 * t + 2];
    const Vec3 n = cross(Vec3(m.vertices[b] - m.vertices[a]), Vec3(m.vertices[c] - m.vertices[a]));
    sum[a] += n;
    sum[b] += n;
    sum[c] += n;
  }
  m.normals.resize(m.vertices.size());
  for (std::uint32_t v = 0; v < m.vertices.size(); ++v) {
    const auto [col, row] = vertices.lattice(v);
    const bool own = vertices.own(v);
    m.normals[v] =
        Vec3f(own ? grid_vertex_normal(field.grid(), static_cast<int>(col), static_cast<int>(row))
                  : (length(sum[v]) > 0.0 ? normalize(sum[v]) : Vec3{0.0, 0.0, 1.0}));
  }
}

}  // namespace

ContextMesh build_context_mesh(const TerrainField& field, const Vec3& origin,
                               const ContextMeshOptions& options) {
  const Quadtree tree(field, options);
  ContextMesh out;
  Vertices vertices(field, origin, tree.col0(), tree.row0(), out);
  Triangulation triangulation(tree, vertices, out);
  for (const Cell& c : tree.leaves()) triangulation.add(c);
  add_normals(field, vertices, out);
  return out;
}

std::size_t count_context_cells(const TerrainField& field, const ContextMeshOptions& options) {
  return Quadtree(field, options).leaves().size();
}

}  // namespace landsim::terrain
