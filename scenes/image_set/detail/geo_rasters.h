#pragma once
// Private to scenes/: an image's georeferenced rasters beside its EXR (docs/OUTPUTS.md
// "GeoTIFF and ENVI"), through the GDAL module: <stem>.tif / <stem>.img with the radiance,
// every band (named, with its centre wavelength), depth, coverage and the world position of
// each pixel's first hit; <stem>_ids.tif / _ids.img with the id layers. A view looking
// straight down through an orthographic lens is a map: a geotransform in the terrain's CRS.
#include <array>
#include <filesystem>
#include <optional>
#include <string>

#include "renderer/output/film.h"
#include "renderer/scene.h"
#include "scenes/scenario/scenario.h"
#include "terrain/raster_io.h"

namespace landsim::scenes::detail {

// GDAL's geotransform of a map view (view in the scene frame, origin its terrain
// coordinates); empty for views that are not maps.
std::optional<std::array<double, 6>> map_geotransform(const renderer::View& view,
                                                      const Vec3& origin);

// Writes `r` (driver "GTiff" or "ENVI") to dir/name.tif or dir/name.img (+ .hdr) under a
// temporary name, renamed when complete; throws std::runtime_error naming the file when GDAL
// fails.
void write_raster_file(const terrain::OutputRaster& r, const std::filesystem::path& dir,
                       const std::string& name);

// Writes the formats `s.render` asks for (nothing without geotiff or envi), with `camera`
// (the camera model as the manifest's JSON) in the metadata; throws std::runtime_error
// naming the file when GDAL fails.
void write_geo_rasters(const renderer::Film& film, const renderer::View& view,
                       const renderer::Scene& scene, const Scenario& s,
                       const std::filesystem::path& dir, const std::string& stem,
                       const std::string& camera);

}  // namespace landsim::scenes::detail
