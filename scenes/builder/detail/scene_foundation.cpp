#include "scenes/builder/detail/scene_foundation.h"

#include "scenes/builder/view_placement.h"

#include <cmath>

#include "scenes/builder/detail/vegetation_input.h"
#include "terrain/dem_loader.h"

namespace landsim::scenes::detail {
namespace {

MaterialRaster material_raster(const std::string& path) {
  if (path.empty()) return {};
  return {terrain::load_elevation(path)};
}

double grid_bytes(const terrain::ElevationGrid& g) {
  return static_cast<double>(g.cols()) * g.rows() * sizeof(float);
}

}  // namespace

bool MaterialRaster::covers(double x, double y) const {
  if (!grid) return false;
  const terrain::GeoTransform& t = grid->transform();
  const double c = (x - t.origin_x) / t.cell_size_x, r = (t.origin_y - y) / t.cell_size_y;
  if (!(c >= 0 && r >= 0 && c < grid->cols() && r < grid->rows())) return false;
  const float v = grid->at(static_cast<int>(c), static_cast<int>(r));
  return !std::isnan(v) && v != 0.0f;
}

double SceneFoundation::bytes() const {
  double total = grid_bytes(grid);
  for (const MaterialRaster& r : rasters)
    if (r.grid) total += grid_bytes(*r.grid);
  // A map cell: its 16-bit code and its 4-byte class or cover index.
  if (map) total += static_cast<double>(map->cols()) * map->rows() * (2.0 + 4.0);
  return total;
}

std::vector<renderer::View> SceneFoundation::views_around(const Vec3& origin) const {
  std::vector<renderer::View> out = views;
  for (renderer::View& v : out) {
    v.position -= origin;
    v.target -= origin;
  }
  return out;
}

SceneFoundation lay_foundation(const Scenario& s) {
  terrain::ElevationGrid grid = terrain::load_elevation(s.terrain.elevation, s.terrain.dem);
  const FeatureMapSettings f = s.featuremaps.value_or(FeatureMapSettings{});
  GroundRasters rasters = {material_raster(f.road), material_raster(f.water),
                           material_raster(f.rock), material_raster(f.soil)};
  std::optional<featuremaps::VegetationMap> map;
  if (s.featuremaps || has_cover(s)) map = scene_vegetation(s, grid);
  std::vector<renderer::View> views;
  for (const ViewSettings& v : s.views) views.push_back(place_view(v, grid));
  return {std::move(grid), std::move(rasters), std::move(map), std::move(views)};
}

}  // namespace landsim::scenes::detail
