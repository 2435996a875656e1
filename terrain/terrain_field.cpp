#include "terrain/terrain_field.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/input_error.h"
#include "terrain/raster_io.h"

namespace landsim::terrain {
namespace {

double cell_size(const ElevationGrid& g) {
  return std::max(g.transform().cell_size_x, g.transform().cell_size_y);
}

// Unknown (NaN) cells not connected to the border through unknown cells: holes inside a
// grid, which are filled from all around rather than faded toward the coarser surface.
std::vector<std::uint8_t> enclosed_cells(const std::vector<float>& cells, int cols, int rows) {
  const auto index = [&](int c, int r) {
    return static_cast<std::size_t>(r) * static_cast<std::size_t>(cols) +
           static_cast<std::size_t>(c);
  };
  std::vector<std::uint8_t> enclosed(cells.size(), 0), outside(cells.size(), 0);
  std::vector<std::pair<int, int>> stack;
  const auto visit = [&](int c, int r) {
    if (c < 0 || r < 0 || c >= cols || r >= rows) return;
    const std::size_t i = index(c, r);
    if (outside[i] || !std::isnan(cells[i])) return;
    outside[i] = 1;
    stack.emplace_back(c, r);
  };
  for (int c = 0; c < cols; ++c) {
    visit(c, 0);
    visit(c, rows - 1);
  }
  for (int r = 0; r < rows; ++r) {
    visit(0, r);
    visit(cols - 1, r);
  }
  while (!stack.empty()) {
    const auto [c, r] = stack.back();
    stack.pop_back();
    visit(c + 1, r);
    visit(c - 1, r);
    visit(c, r + 1);
    visit(c, r - 1);
  }
  for (std::size_t i = 0; i < cells.size(); ++i)
    enclosed[i] = std::isnan(cells[i]) && !outside[i] ? 1 : 0;
  return enclosed;
}

}  // namespace

TerrainField::TerrainField(const ElevationGrid& grid, std::vector<ElevationGrid> contexts)
    : grid_(grid), contexts_(std::move(contexts)) {
  std::stable_sort(
      contexts_.begin(), contexts_.end(),
      [](const ElevationGrid& a, const ElevationGrid& b) { return cell_size(a) < cell_size(b); });
  layers_.push_back(Layer{&grid_, std::nullopt});
  for (const ElevationGrid& c : contexts_) layers_.push_back(Layer{&c, std::nullopt});
  extent_ = {1e300, 1e300, -1e300, -1e300};
  for (const Layer& l : layers_) {
    const GeoTransform& t = l.grid->transform();
    extent_[0] = std::min(extent_[0], t.origin_x);
    extent_[1] = std::min(extent_[1], t.origin_y - l.grid->rows() * t.cell_size_y);
    extent_[2] = std::max(extent_[2], t.origin_x + l.grid->cols() * t.cell_size_x);
    extent_[3] = std::max(extent_[3], t.origin_y);
  }
  // The coarsest surface stands as it is; each finer one bends the one below it.
  for (std::size_t k = layers_.size() - 1; k-- > 0;) blend(k);
}

double TerrainField::finest_context_cell() const {
  return contexts_.empty() ? cell_size(grid_) : cell_size(contexts_.front());
}

double TerrainField::stored_cells() const {
  double cells = 0.0;
  for (const ElevationGrid& c : contexts_) cells += static_cast<double>(c.cols()) * c.rows();
  for (const Layer& l : layers_)
    if (l.offsets) cells += static_cast<double>(l.offsets->cols()) * l.offsets->rows();
  return cells;
}

bool TerrainField::from_grid(long col, long row) const {
  return col >= 0 && row >= 0 && col < grid_.cols() && row < grid_.rows() &&
         grid_.valid(static_cast<int>(col), static_cast<int>(row));
}

std::optional<double> TerrainField::lattice_height(long col, long row) const {
  if (from_grid(col, row)) return grid_.at(static_cast<int>(col), static_cast<int>(row));
  if (layers_.size() < 2) return std::nullopt;
  const double x = grid_.x_of_col(static_cast<double>(col));
  const double y = grid_.y_of_row(static_cast<double>(row));
  const std::optional<double> below = layer_height(1, x, y);
  if (!below) return std::nullopt;
  return *below + offset(layers_[0], x, y);
}

std::optional<double> TerrainField::height(double x, double y) const {
  return layer_height(0, x, y);
}

std::optional<double> TerrainField::layer_height(std::size_t k, double x, double y) const {
  if (const std::optional<double> own = layers_[k].grid->height(x, y)) return own;
  if (k + 1 >= layers_.size()) return std::nullopt;
  const std::optional<double> below = layer_height(k + 1, x, y);
  if (!below) return std::nullopt;
  return *below + offset(layers_[k], x, y);
}

// Offsets of layer k: at its valid samples, its height minus the coarser surface's; around
// them, fading to zero over the blend band (GDAL fills and measures, terrain/raster_io.h).
void TerrainField::blend(std::size_t k) {
  Layer& layer = layers_[k];
  const ElevationGrid& g = *layer.grid;
  const double band =
      std::min(kBlendCells * cell_size(*layers_[k + 1].grid) / cell_size(g), kMaxBlendCells);
  const int margin = static_cast<int>(std::ceil(band)) + 1;
  const int cols = g.cols() + 2 * margin, rows = g.rows() + 2 * margin;
  std::vector<float> offsets(static_cast<std::size_t>(cols) * static_cast<std::size_t>(rows), NAN);
  for (int r = 0; r < g.rows(); ++r) {
    for (int c = 0; c < g.cols(); ++c) {
      if (!g.valid(c, r)) continue;
      const std::optional<double> below = layer_height(k + 1, g.x_of_col(c), g.y_of_row(r));
      if (!below) continue;
      offsets[static_cast<std::size_t>(r + margin) * static_cast<std::size_t>(cols) +
              static_cast<std::size_t>(c + margin)] = static_cast<float>(g.at(c, r) - *below);
    }
  }
  const std::vector<std::uint8_t> enclosed = enclosed_cells(offsets, cols, rows);
  std::string error;
  if (!raster_io().fade_offsets(offsets.data(), enclosed.data(), cols, rows, band, error))
    throw std::runtime_error("blending the context grids failed (GDAL: " + error + ")");
  const GeoTransform& t = g.transform();
  layer.offsets.emplace(
      cols, rows,
      GeoTransform{t.origin_x - margin * t.cell_size_x, t.origin_y + margin * t.cell_size_y,
                   t.cell_size_x, t.cell_size_y},
      std::move(offsets));
}

}  // namespace landsim::terrain
