#include "scenes/scenario/detail/terrain_reader.h"

#include "core/input_error.h"
#include "params/table_reader.h"
#include "scenes/scenario/detail/relative_path.h"
#include "scenes/scenario/detail/toml_tables.h"
#include "terrain/raster_files.h"

namespace landsim::scenes::detail {

namespace {

using params::Range;
using params::TableReader;

// [terrain] context: coarser elevation rasters around the grid, each checked to exist.
std::vector<std::string> read_context(TableReader& r, const std::string& base_dir,
                                      std::vector<std::string>& locations) {
  std::vector<std::string> paths;
  const toml::node* n =
      r.value("context", "an array of raster files: coarser elevation grids around the grid", "[]");
  if (n == nullptr) return paths;
  const toml::array* files = n->as_array();
  if (files == nullptr)
    r.fail_at(*n, "context", "expected an array of file names, such as [\"region.tif\"]");
  for (const toml::node& f : *files) {
    if (!f.is_string()) r.fail_at(f, "context", "expected a file name (a string)");
    paths.push_back(resolve(base_dir, *f.value<std::string>()));
    locations.push_back(r.location(&f));
    if (!terrain::raster_file_exists(paths.back()))
      r.fail_at(f, "context", "file not found: " + paths.back());
  }
  return paths;
}

}  // namespace

TerrainSettings read_terrain(const toml::table& t, const std::string& file,
                             const std::string& base_dir) {
  TableReader r(t, "terrain", file);
  TerrainSettings s;
  s.elevation = resolve(base_dir, r.string("elevation"));
  if (!terrain::raster_file_exists(s.elevation)) {
    r.fail("elevation", "file not found: " + s.elevation);
  }
  s.dem.cell_size = r.optional_number("cell_size", kPositive);
  if (const auto o = r.optional_numbers("origin", 2, Range{-1e12, 1e12})) {
    s.dem.origin = std::array<double, 2>{(*o)[0], (*o)[1]};
  }
  s.dem.height_scale = r.number("height_scale", Range{-1e6, 1e6}, s.dem.height_scale);
  if (s.dem.height_scale == 0.0) r.fail("height_scale", "expected a non-zero number, got 0");
  s.dem.height_offset = r.number("height_offset", Range{-1e6, 1e6}, s.dem.height_offset);
  const std::string nodata = r.choice("nodata", {"hole", "fill"}, "hole");
  s.dem.nodata = nodata == "fill" ? terrain::NodataPolicy::fill : terrain::NodataPolicy::hole;
  s.albedo = to_vec3f(r.vec3("albedo", kUnit, Vec3(s.albedo)));
  s.context = read_context(r, base_dir, s.context_locations);
  s.periodic = r.boolean("periodic", s.periodic);
  if (s.periodic && !s.context.empty())
    r.fail("periodic", "a periodic cell repeats the grid itself: it takes no context grids");
  r.finish();
  return s;
}

}  // namespace landsim::scenes::detail
