#include "scenes/image_set/detail/geo_rasters.h"

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "core/atomic_file.h"
#include "renderer/acceleration/embree_scene.h"
#include "renderer/camera.h"
#include "renderer/output/image_output.h"
#include "terrain/raster_io.h"

namespace landsim::scenes::detail {
namespace {

using terrain::CellType;
using terrain::GroundControlPoint;
using terrain::OutputBand;
using terrain::OutputRaster;

// A band's centre wavelength: its response's centroid, as the sensor's channels have theirs.
std::optional<double> centre_wavelength(const BandSettings& b) {
  const double nm = renderer::centroid_wavelength(b.response);
  if (nm <= 0.0) return std::nullopt;
  return nm;
}

// One plane of a film's interleaved data (stride values a pixel).
std::vector<float> plane(const std::vector<float>& data, int stride, int offset) {
  std::vector<float> out(data.size() / static_cast<std::size_t>(stride));
  for (std::size_t i = 0; i < out.size(); ++i)
    out[i] = data[i * static_cast<std::size_t>(stride) + static_cast<std::size_t>(offset)];
  return out;
}

// The world position planes: the terrain's CRS less `origin` (float keeps a millimetre within
// tens of kilometres of it; UTM eastings themselves would keep a decimetre at best).
std::array<std::vector<float>, 3> world_planes(const renderer::Film& film) {
  return {plane(film.position_data(), 3, 0), plane(film.position_data(), 3, 1),
          plane(film.position_data(), 3, 2)};
}

// A map pixel with no DEM under it: the plain, the sky, no ray.
bool off_the_dem(std::uint32_t object) {
  using renderer::ObjectClass;
  return object == static_cast<std::uint32_t>(ObjectClass::plain) ||
         object == static_cast<std::uint32_t>(ObjectClass::sky) ||
         object == static_cast<std::uint32_t>(ObjectClass::none);
}

// GCPs per side of the lattice a view without a geotransform is placed by.
constexpr int kGcpLattice = 8;

// Ground control points of a view that is not a map: on a lattice of pixels, those whose
// first hit is ground, each at the image position its hit projects to (exact, where the
// pixel's jittered sample fell) and its terrain coordinates.
std::vector<GroundControlPoint> control_points(const renderer::Film& film,
                                               const renderer::View& view, const Vec3& origin) {
  std::vector<GroundControlPoint> out;
  const renderer::Camera camera(view);
  for (int j = 0; j < kGcpLattice; ++j)
    for (int i = 0; i < kGcpLattice; ++i) {
      const int x = static_cast<int>((i + 0.5) * film.width() / kGcpLattice);
      const int y = static_cast<int>((j + 0.5) * film.height() / kGcpLattice);
      const std::size_t k = static_cast<std::size_t>(y) * film.width() + x;
      if (film.object_data()[k] != static_cast<std::uint32_t>(renderer::ObjectClass::ground))
        continue;
      const Vec3 p{film.position_data()[3 * k], film.position_data()[3 * k + 1],
                   film.position_data()[3 * k + 2]};
      const std::optional<renderer::ImagePoint> at = camera.project(p);
      if (!at) continue;
      out.push_back({at->x, at->y, p.x + origin.x, p.y + origin.y, p.z + origin.z});
    }
  return out;
}

}  // namespace

void write_raster_file(const terrain::OutputRaster& r, const std::filesystem::path& dir,
                       const std::string& name) {
  const bool envi = r.driver == "ENVI";
  const std::filesystem::path path = dir / (name + (envi ? ".img" : ".tif"));
  AtomicFile out(path);
  std::string error;
  if (!terrain::raster_io().write_raster(out.temp_path().string(), r, error))
    throw std::runtime_error("writing " + path.string() + " failed: " + error);
  if (envi) {  // GDAL names the header after the data file, extension replaced
    std::filesystem::path header = out.temp_path();
    header.replace_extension(".hdr");
    std::filesystem::rename(header, dir / (name + ".hdr"));
  }
  out.commit();
}

std::optional<std::array<double, 6>> map_geotransform(const renderer::View& view,
                                                      const Vec3& origin) {
  if (view.lens.projection != renderer::Projection::orthographic) return std::nullopt;
  const renderer::CameraBasis b = renderer::camera_basis(view);
  if (b.forward.z > -1.0 + 1e-12) return std::nullopt;  // not straight down: not a map
  const double pw = view.lens.extent_width / view.width, ph = view.lens.extent_height / view.height;
  const Vec3 centre = view.position + origin;
  // Pixel (col, row)'s corner: centre + (col - W/2) pw right - (row - H/2) ph up.
  return std::array<double, 6>{
      centre.x - 0.5 * view.lens.extent_width * b.right.x + 0.5 * view.lens.extent_height * b.up.x,
      pw * b.right.x,
      -ph * b.up.x,
      centre.y - 0.5 * view.lens.extent_width * b.right.y + 0.5 * view.lens.extent_height * b.up.y,
      pw * b.right.y,
      -ph * b.up.y};
}

void write_geo_rasters(const renderer::Film& film, const renderer::View& view,
                       const renderer::Scene& scene, const Scenario& s,
                       const std::filesystem::path& dir, const std::string& stem,
                       const std::string& camera) {
  if (!s.render.geotiff && !s.render.envi) return;
  const std::vector<float> r = plane(film.rgb_data(), 3, 0), g = plane(film.rgb_data(), 3, 1),
                           bl = plane(film.rgb_data(), 3, 2);
  std::vector<float> y(film.pixel_count());
  for (std::size_t i = 0; i < y.size(); ++i)
    y[i] = 0.2126f * r[i] + 0.7152f * g[i] + 0.0722f * bl[i];
  const auto world = world_planes(film);
  OutputRaster values;
  values.cols = film.width();
  values.rows = film.height();
  values.bands = {
      {"R", r.data(), {}}, {"G", g.data(), {}}, {"B", bl.data(), {}}, {"Y", y.data(), {}}};
  // The film's planes: the bands, then the sensor's channels, then derived layers.
  const std::size_t bands = s.bands.size(),
                    channels = s.sensor ? s.sensor->model.channels.size() : 0;
  for (int b = 0; b < film.band_count(); ++b) {
    const auto i = static_cast<std::size_t>(b);
    std::optional<double> wavelength;
    if (i < bands)
      wavelength = centre_wavelength(s.bands[i]);
    else if (i < bands + channels)
      wavelength = s.sensor->model.channels[i - bands].wavelength_nm;
    values.bands.push_back(
        {renderer::band_layer(film.band_name(b)), film.band_data(b).data(), wavelength});
  }
  values.bands.push_back({"Z", film.depth_data().data(), {}});
  values.bands.push_back({"coverage", film.coverage_data().data(), {}});
  values.bands.push_back({"world_x", world[0].data(), {}});
  values.bands.push_back({"world_y", world[1].data(), {}});
  values.bands.push_back({"world_z", world[2].data(), {}});
  values.geotransform = map_geotransform(view, scene.origin);
  if (!values.geotransform && !scene.crs_wkt.empty())
    values.gcps = control_points(film, view, scene.origin);
  values.crs_wkt = scene.crs_wkt;
  values.metadata = {{"landsim_view", view.name},
                     {"landsim_camera", camera},
                     {"landsim_world_origin",
                      fmt::format("{} {} {}", scene.origin.x, scene.origin.y, scene.origin.z)},
                     {"landsim_world",
                      "world_x, world_y, world_z: the first hit in the terrain's CRS less "
                      "landsim_world_origin, metres; NaN where nothing is hit"},
                     {"landsim_radiance_unit", "R, G, B, Y: cd/m2 (Y); band.*: W m-2 sr-1"}};
  OutputRaster ids = values;
  // A map's float bands are NoData (NaN) where no DEM stands: the plain beyond the grid and
  // over its holes (its own object class), and sky; the ids keep their classes.
  std::vector<std::vector<float>> masked;
  if (values.geotransform) {
    masked.reserve(values.bands.size());
    for (OutputBand& band : values.bands) {
      const auto* cells = static_cast<const float*>(band.cells);
      std::vector<float>& copy = masked.emplace_back(cells, cells + film.pixel_count());
      for (std::size_t i = 0; i < copy.size(); ++i)
        if (off_the_dem(film.object_data()[i])) copy[i] = std::numeric_limits<float>::quiet_NaN();
      band.cells = copy.data();
    }
    values.nodata = std::numeric_limits<double>::quiet_NaN();
  }
  ids.type = CellType::uint32;
  ids.bands = {{"object", film.object_data().data(), {}},
               {"species", film.species_data().data(), {}},
               {"instance", film.instance_data().data(), {}},
               {"lod", film.level_data().data(), {}},
               {"target", film.target_data().data(), {}}};
  for (const char* driver : {"GTiff", "ENVI"}) {
    if (std::string(driver) == "GTiff" ? !s.render.geotiff : !s.render.envi) continue;
    values.driver = ids.driver = driver;
    write_raster_file(values, dir, stem);
    write_raster_file(ids, dir, stem + "_ids");
  }
}

}  // namespace landsim::scenes::detail
