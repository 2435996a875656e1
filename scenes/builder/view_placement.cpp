#include "scenes/builder/view_placement.h"

#include <fmt/format.h>

#include <cmath>

#include "core/input_error.h"

namespace landsim::scenes {
namespace {

// Height above the grid's highest ground of a map view's camera: above any tree or object.
constexpr double kMapCameraClearance = 1000.0;

// An orthographic view looking straight down with each pixel on `k` x `k` cells, its edges on
// cell edges, north up.
void align_to_grid(renderer::View& out, const ViewSettings& v, const terrain::ElevationGrid& grid) {
  const terrain::GeoTransform& t = grid.transform();
  const int k = v.grid_cells_per_pixel;
  const double px = k * t.cell_size_x, py = k * t.cell_size_y;
  if (!v.has_size) {
    out.width = (grid.cols() + k - 1) / k;
    out.height = (grid.rows() + k - 1) / k;
    check_image_size(out.width, out.height, v.location + ": [views \"" + v.name + "\"] align");
  }
  out.lens.extent_width = out.width * px;
  out.lens.extent_height = out.height * py;
  // The frame's west and north edges: the grid's own, or the position's snapped to cells.
  double west = t.origin_x, north = t.origin_y;
  if (v.has_position) {
    west = t.origin_x +
           std::round((v.position.x - 0.5 * out.lens.extent_width - t.origin_x) / t.cell_size_x) *
               t.cell_size_x;
    north = t.origin_y - std::round((t.origin_y - (v.position.y + 0.5 * out.lens.extent_height)) /
                                    t.cell_size_y) *
                             t.cell_size_y;
  }
  const double z = v.has_position ? v.position.z : grid.max_height() + kMapCameraClearance;
  out.position = {west + 0.5 * out.lens.extent_width, north - 0.5 * out.lens.extent_height, z};
  out.target = out.position - Vec3{0.0, 0.0, 1000.0};
  out.up = {0.0, 0.0, 1.0};
  out.heading_deg = 0.0;  // north up
  out.roll_deg = 0.0;
}

[[noreturn]] void fail(const ViewSettings& v, const std::string& message) {
  throw InputError(fmt::format("{}: [views \"{}\"] {}", v.location, v.name, message));
}

}  // namespace

renderer::View place_view(const ViewSettings& v, const terrain::ElevationGrid& grid) {
  renderer::View out = v;
  if (v.grid_cells_per_pixel > 0) {
    align_to_grid(out, v, grid);
    return out;
  }
  if (v.altitude_above_ground) {
    const std::optional<double> ground = grid.height(v.position.x, v.position.y);
    if (!ground)
      fail(v, fmt::format("altitude_above_ground: there is no ground under ({}, {}) (outside the "
                          "elevation grid, or a nodata cell); give position's z instead",
                          v.position.x, v.position.y));
    out.position.z = *ground + *v.altitude_above_ground;
    if (!v.aims_at_point) out.target.z += out.position.z - v.position.z;
  }
  const Vec3 axis = out.target - out.position;
  if (length(axis) < 1e-6) fail(v, "target: must differ from the placed position");
  if (v.up != Vec3{0.0, 0.0, 1.0} && length(cross(normalize(axis), v.up)) < 1e-6)
    fail(v, "up: is parallel to the view's axis; the image's up needs a direction across it");
  return out;
}

}  // namespace landsim::scenes
