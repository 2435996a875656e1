#pragma once
// Detail below the grid's cells: seeded fractal relief that leaves every grid sample where it
// is. Grids are 5-30 m per cell; between samples their surface is flat facets. The relief
// at a point is the bilinear blend, over the four samples around it, of each sample's
//   amplitude x (F(point) - F(sample)) / 2,
// F being fractal value noise in [-1, 1] whose wavelength is the cell and whose roughness
// is the sample's: zero at every sample, continuous everywhere, at most the largest
// amplitude around (docs/GROUND.md).
#include <cstdint>
#include <vector>

#include "terrain/elevation_grid.h"

namespace landsim::terrain {

inline constexpr int kDetailOctaves = 4;

class SurfaceDetail {
 public:
  // Per grid cell (row-major, north first like the grid): amplitude (metres) and roughness
  // (0-1, the amplitude kept from one octave to the next).
  SurfaceDetail(const ElevationGrid& grid, std::vector<float> amplitude,
                std::vector<float> roughness, std::uint64_t seed);

  // The relief at (x, y), grid coordinates; 0 outside the grid's valid samples.
  double displacement(double x, double y) const;
  // The largest amplitude of any sample.
  double max_amplitude() const { return max_amplitude_; }

 private:
  double noise(double x, double y, float roughness) const;

  const ElevationGrid& grid_;
  std::vector<float> amplitude_, roughness_;
  std::uint64_t seed_;
  double max_amplitude_ = 0.0;
};

}  // namespace landsim::terrain
