// Writes a context elevation grid around a DEM for the ground benchmark (bench/ground.sh):
// no real regional DEM of the Kagwene area ships with landsim, so this one is synthetic. It
// carries the DEM's own heights (resampled to the context's cells) where the DEM has data,
// continues them smoothly outward (GDAL's nodata fill), and adds seeded fractal relief that
// grows with distance from the DEM, so that hills and valleys surround the sanctuary.
//   context_grid DEM OUT.tif [SIZE_KM=100] [CELL_M=90] [SEED=1]
// OUT is a UInt16 GeoTIFF (metres) in the DEM's coordinate reference system.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <exception>
#include <string>
#include <vector>

#include "core/value_noise.h"
#include "terrain/dem_loader.h"
#include "terrain/raster_io.h"

namespace {

using landsim::terrain::ElevationGrid;

constexpr double kReliefMetres = 450.0;     // amplitude of the added relief far out
constexpr double kReliefWavelength = 9000;  // metres, its longest wavelength
constexpr double kFadeMetres = 3000.0;      // the DEM's heights give way over this distance

double distance_outside(const ElevationGrid& g, double x, double y) {
  const auto& t = g.transform();
  const double west = t.origin_x, east = t.origin_x + g.cols() * t.cell_size_x;
  const double north = t.origin_y, south = t.origin_y - g.rows() * t.cell_size_y;
  return std::hypot(std::max({0.0, west - x, x - east}), std::max({0.0, south - y, y - north}));
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    fmt::print(stderr, "usage: context_grid DEM OUT.tif [SIZE_KM=100] [CELL_M=90] [SEED=1]\n");
    return 2;
  }
  try {
    const ElevationGrid dem = landsim::terrain::load_elevation(argv[1]);
    const double size = (argc > 3 ? std::atof(argv[3]) : 100.0) * 1000.0;
    const double cell = argc > 4 ? std::atof(argv[4]) : 90.0;
    const std::uint64_t seed = argc > 5 ? std::strtoull(argv[5], nullptr, 10) : 1;
    const int n = static_cast<int>(std::ceil(size / cell));
    const landsim::Vec3 centre = dem.centre();
    const double west = centre.x - 0.5 * n * cell, north = centre.y + 0.5 * n * cell;
    constexpr float kUnknown = -1e30f;
    std::vector<float> h(static_cast<std::size_t>(n) * static_cast<std::size_t>(n), kUnknown);
    for (int r = 0; r < n; ++r)
      for (int c = 0; c < n; ++c)
        if (const auto z = dem.height(west + (c + 0.5) * cell, north - (r + 0.5) * cell))
          h[static_cast<std::size_t>(r) * n + c] = static_cast<float>(*z);
    std::string error;
    if (!landsim::terrain::raster_io().fill_nodata(h.data(), n, n, kUnknown, error))
      throw std::runtime_error("fill failed: " + error);
    std::vector<std::uint16_t> out(h.size());
    for (int r = 0; r < n; ++r)
      for (int c = 0; c < n; ++c) {
        const double x = west + (c + 0.5) * cell, y = north - (r + 0.5) * cell;
        const double away = 1.0 - std::exp(-distance_outside(dem, x, y) / kFadeMetres);
        const double relief =
            kReliefMetres * landsim::fractal_noise(x, y, kReliefWavelength, 7, 0.5, seed);
        const std::size_t i = static_cast<std::size_t>(r) * n + c;
        out[i] = static_cast<std::uint16_t>(std::clamp(h[i] + away * relief, 1.0, 65000.0));
      }
    const std::array<double, 6> gt{west, cell, 0.0, north, 0.0, -cell};
    if (!landsim::terrain::raster_io().write_uint16_geotiff(argv[2], n, n, out.data(), gt,
                                                            dem.crs_wkt(), error))
      throw std::runtime_error("write failed: " + error);
    fmt::print("{}: {} x {} cells of {} m, {:.0f} km square around {}\n", argv[2], n, n, cell,
               size / 1000.0, argv[1]);
  } catch (const std::exception& e) {
    fmt::print(stderr, "context_grid: {}\n", e.what());
    return 1;
  }
  return 0;
}
