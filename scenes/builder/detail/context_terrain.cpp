#include "scenes/builder/detail/context_terrain.h"

#include <fmt/format.h>

#include <cmath>

#include "core/input_error.h"
#include "terrain/context_grid.h"
#include "terrain/raster_files.h"
#include "terrain/raster_io.h"

namespace landsim::scenes::detail {

namespace {

// How far [terrain] origin moved the grid from its file's placement (contexts move with it);
// a cell size other than the file's would stretch the grid away from its context: refused.
std::array<double, 2> placement_shift(const Scenario& s, const terrain::ElevationGrid& grid) {
  terrain::share_with_gdal(s.terrain.elevation);
  terrain::RasterHeader header;
  std::string error;
  if (!terrain::raster_io().read_header(s.terrain.elevation, header, error) || !header.geotransform)
    return {0.0, 0.0};  // no placement of its own: the scenario's is the only one
  const std::array<double, 6>& gt = *header.geotransform;
  const terrain::GeoTransform& t = grid.transform();
  if (std::abs(t.cell_size_x - gt[1]) > 1e-9 * gt[1] ||
      std::abs(t.cell_size_y + gt[5]) > 1e-9 * std::abs(gt[5]))
    throw InputError(fmt::format(
        "{}: [terrain] context: cell_size {} differs from the elevation file's own ({} x {}): "
        "the grid would no longer lie on its context grids",
        s.terrain.context_locations.empty() ? s.source : s.terrain.context_locations[0],
        t.cell_size_x, gt[1], -gt[5]));
  return {t.origin_x - gt[0], t.origin_y - gt[3]};
}

}  // namespace

terrain::TerrainField context_terrain(const Scenario& s, const terrain::ElevationGrid& grid) {
  std::vector<terrain::ElevationGrid> contexts;
  if (s.terrain.context.empty()) return terrain::TerrainField(grid, {});  // detail alone
  const std::array<double, 2> shift = placement_shift(s, grid);
  for (std::size_t k = 0; k < s.terrain.context.size(); ++k) {
    try {
      contexts.push_back(terrain::load_context(s.terrain.context[k], grid, shift));
    } catch (const InputError& e) {
      const std::string where =
          k < s.terrain.context_locations.size() ? s.terrain.context_locations[k] + ": " : "";
      throw InputError(where + "[terrain] context: " + e.what());
    }
  }
  return terrain::TerrainField(grid, std::move(contexts));
}

}  // namespace landsim::scenes::detail
