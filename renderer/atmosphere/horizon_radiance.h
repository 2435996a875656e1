#pragma once
// The sky's horizon band radiance (SkyModel::horizon_band_radiance) by azimuth, tabulated: the
// haze's ambient (multiply scattered) light is sized from it on every ray segment, where evaluating
// the sky model each time cost several percent of a forest render (docs/PERFORMANCE.md "Forest
// scale"). 4096 steps of about a tenth of a degree, linearly interpolated: the horizon's radiance
// varies slowly with azimuth.
#include <vector>

#include "core/vec3.h"
#include "renderer/atmosphere/sky.h"

namespace landsim::renderer {

class HorizonRadiance {
 public:
  explicit HorizonRadiance(const SkyModel& sky);
  // At the azimuth of `direction` (any length); straight up or down, the sky's mean.
  Vec3f radiance(const Vec3f& direction) const;
  // The same spectrally (SkyModel::horizon_band_spectral).
  Spectrum spectral(const Vec3f& direction) const;

 private:
  std::vector<Vec3f> table_;  // kSteps + 1 entries, the last equal to the first
  Vec3f mean_;
  std::vector<Spectrum> spectral_table_;
  Spectrum mean_spectrum_;
};

}  // namespace landsim::renderer
