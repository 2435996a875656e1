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

// A quadtree cell: its north-west point on the fine lattice (the grid's lattice divided
// 2^detail_levels times when there is detail) and its level (it spans 2^level fine cells).
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
    grid_level_ = options.detail != nullptr ? options.detail_levels : 0;
    sub_ = 1L << grid_level_;
    const auto [west, south, east, north] = field.extent();
    const long col0 = static_cast<long>(std::floor((west - t.origin_x) / t.cell_size_x - 0.5));
    const long row0 = static_cast<long>(std::floor((t.origin_y - north) / t.cell_size_y - 0.5));
    const long cols =
        static_cast<long>(std::ceil((east - t.origin_x) / t.cell_size_x - 0.5)) - col0;
    const long rows =
        static_cast<long>(std::ceil((t.origin_y - south) / t.cell_size_y - 0.5)) - row0;
    col0_ = col0 * sub_;
    row0_ = row0 * sub_;
    while ((1L << root_level_) < std::max({cols, rows, 1L}) * sub_) ++root_level_;
    cell_metres_ = std::max(t.cell_size_x, t.cell_size_y) / static_cast<double>(sub_);
    subdivide();
  }

  long sub() const { return sub_; }

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
    const auto at = [&](long fine) {
      return static_cast<double>(fine) / static_cast<double>(sub_);
    };
    return {g.x_of_col(at(c.col)), g.y_of_row(at(c.row + c.span())),
            g.x_of_col(at(c.col + c.span())), g.y_of_row(at(c.row))};
  }

  static bool near_a_view(const std::vector<std::array<double, 2>>& views,
                          const std::array<double, 4>& b, double reach) {
    for (const auto& v : views) {
      const double dx = std::max({0.0, b[0] - v[0], v[0] - b[2]});
      const double dy = std::max({0.0, b[1] - v[1], v[1] - b[3]});
      if (std::hypot(dx, dy) < reach) return true;
    }
    return false;
  }

  bool has_data(const std::array<double, 4>& b) const {
    const auto e = field_.extent();
    return b[0] < e[2] && b[2] > e[0] && b[1] < e[3] && b[3] > e[1];
  }

  bool wants_split(const Cell& c, const std::array<double, 4>& b) const {
    const ElevationGrid& g = field_.grid();
    const double size = cell_metres_ * static_cast<double>(c.span());
    // Detail: below the grid's cells, near the views, on the grid.
    if (options_.detail != nullptr && on_grid(b) &&
        near_a_view(options_.views, b, options_.detail_factor * size))
      return true;
    if (c.level <= grid_level_) return false;
    // Near the grid, in grid cells: the grid itself is at the grid's level.
    const auto fine = [&](long v) { return static_cast<double>(v) / static_cast<double>(sub_); };
    const double dc = std::max({0.0, -fine(c.col + c.span()), fine(c.col) - (g.cols() - 1)});
    const double dr = std::max({0.0, -fine(c.row + c.span()), fine(c.row) - (g.rows() - 1)});
    if (std::hypot(dc, dr) < kGridReach * fine(c.span())) return true;
    // Near a view, in metres, while the halves are no finer than the finest context cell.
    if (0.5 * size < field_.finest_context_cell()) return false;
    return near_a_view(options_.views, b, options_.range_factor * size);
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

  bool on_grid(const std::array<double, 4>& b) const {
    const ElevationGrid& g = field_.grid();
    const double west = g.x_of_col(0.0), east = g.x_of_col(g.cols() - 1.0);
    const double north = g.y_of_row(0.0), south = g.y_of_row(g.rows() - 1.0);
    return b[0] < east && b[2] > west && b[1] < north && b[3] > south;
  }

  const TerrainField& field_;
  const ContextMeshOptions& options_;
  long col0_ = 0, row0_ = 0;
  int grid_level_ = 0;  // the level of one grid cell
  long sub_ = 1;        // fine lattice cells per grid cell
  int root_level_ = 0;
  double cell_metres_ = 1.0;
  std::vector<Cell> leaves_;
  std::unordered_set<std::uint64_t> internal_;
};

constexpr std::uint32_t kNoVertex = std::numeric_limits<std::uint32_t>::max();

// Vertices at lattice points, made once each; kNoVertex where no grid has data.
class Vertices {
 public:
  Vertices(const TerrainField& field, const Vec3& origin, const Quadtree& tree,
           const SurfaceDetail* detail, ContextMesh& out)
      : field_(field),
        origin_(origin),
        col0_(tree.col0()),
        row0_(tree.row0()),
        sub_(tree.sub()),
        detail_(detail),
        out_(out) {}

  // The vertex at fine lattice point (col, row): on the grid's lattice its height (exact at
  // the grid's samples); between, the surface there plus the detail's relief.
  std::uint32_t at(long col, long row) {
    const std::uint64_t k =
        (static_cast<std::uint64_t>(col - col0_) << 32) | static_cast<std::uint64_t>(row - row0_);
    const auto [it, inserted] = index_.try_emplace(k, kNoVertex);
    if (!inserted) return it->second;
    const ElevationGrid& g = field_.grid();
    const double fc = static_cast<double>(col) / static_cast<double>(sub_);
    const double fr = static_cast<double>(row) / static_cast<double>(sub_);
    const double x = g.x_of_col(fc), y = g.y_of_row(fr);
    std::optional<double> h;
    bool own = false;
    if (col % sub_ == 0 && row % sub_ == 0) {
      const long gc = static_cast<long>(std::floor(fc)), gr = static_cast<long>(std::floor(fr));
      h = field_.lattice_height(gc, gr);
      own = field_.from_grid(gc, gr);
    } else {
      h = field_.height(x, y);
      own = g.height(x, y).has_value();
      if (h && detail_ != nullptr) *h += detail_->displacement(x, y);
    }
    if (!h) return kNoVertex;
    it->second = static_cast<std::uint32_t>(out_.mesh.vertices.size());
    out_.mesh.vertices.push_back(Vec3f(Vec3{x, y, *h} - origin_));
    own_.push_back(own);
    grid_sample_.push_back(own && col % sub_ == 0 && row % sub_ == 0 && detail_ == nullptr
                               ? std::array<long, 2>{col / sub_, row / sub_}
                               : std::array<long, 2>{-1, -1});
    return it->second;
  }

  // On the grid's surface (not a context's).
  bool own(std::uint32_t v) const { return own_[v]; }
  // The grid sample whose normal the vertex keeps; {-1, -1}: its triangles' mean instead
  // (context vertices, and every vertex of a displaced surface).
  std::array<long, 2> grid_sample(std::uint32_t v) const { return grid_sample_[v]; }

 private:
  const TerrainField& field_;
  Vec3 origin_;
  long col0_, row0_, sub_;
  const SurfaceDetail* detail_;
  ContextMesh& out_;
  std::unordered_map<std::uint64_t, std::uint32_t> index_;
  std::vector<bool> own_;
  std::vector<std::array<long, 2>> grid_sample_;
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

// The grid's own samples keep the grid mesh's normals (without detail); the others average
// their triangles'.
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
    const auto [col, row] = vertices.grid_sample(v);
    m.normals[v] = Vec3f(
        col >= 0 ? grid_vertex_normal(field.grid(), static_cast<int>(col), static_cast<int>(row))
                 : (length(sum[v]) > 0.0 ? normalize(sum[v]) : Vec3{0.0, 0.0, 1.0}));
  }
}

}  // namespace

ContextMesh build_context_mesh(const TerrainField& field, const Vec3& origin,
                               const ContextMeshOptions& options) {
  const Quadtree tree(field, options);
  ContextMesh out;
  Vertices vertices(field, origin, tree, options.detail, out);
  Triangulation triangulation(tree, vertices, out);
  for (const Cell& c : tree.leaves()) triangulation.add(c);
  add_normals(field, vertices, out);
  return out;
}

std::size_t count_context_cells(const TerrainField& field, const ContextMeshOptions& options) {
  return Quadtree(field, options).leaves().size();
}

}  // namespace landsim::terrain
