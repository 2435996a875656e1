#include "renderer/measures/measure_directions.h"

#include <fmt/format.h>

#include <cmath>

#include "core/input_error.h"

namespace landsim::renderer {
namespace {

double wrapped(double degrees) {
  const double a = std::fmod(degrees, 360.0);
  return a < 0.0 ? a + 360.0 : a;
}

}  // namespace

double rami_relative_azimuth(double compass_azimuth_deg, double sun_azimuth_deg) {
  // Counter-clockwise seen from above is the compass turning back.
  return wrapped(sun_azimuth_deg - compass_azimuth_deg);
}

double compass_azimuth(double rami_relative_azimuth_deg, double sun_azimuth_deg) {
  return wrapped(sun_azimuth_deg - rami_relative_azimuth_deg);
}

std::vector<DistantDirection> hemisphere_grid(double zenith_step, double azimuth_step,
                                              double sun_azimuth_deg, bool rami_frame) {
  if (!(zenith_step > 0.0 && zenith_step <= 90.0) || !(azimuth_step > 0.0 && azimuth_step <= 360.0))
    throw InputError(fmt::format(
        "--hemisphere {},{}: expected zenith step in (0, 90] and azimuth step in (0, 360] degrees",
        zenith_step, azimuth_step));
  const auto zeniths = static_cast<long>(std::ceil(90.0 / zenith_step));  // 0 included, 90 not
  const auto azimuths = static_cast<long>(std::ceil(360.0 / azimuth_step));
  if (1 + (zeniths - 1) * azimuths > kMostGridDirections)
    throw InputError(
        fmt::format("--hemisphere {},{}: {} directions, more than {}: take larger steps",
                    zenith_step, azimuth_step, 1 + (zeniths - 1) * azimuths, kMostGridDirections));
  std::vector<DistantDirection> out;
  const double at_nadir = rami_frame ? compass_azimuth(0.0, sun_azimuth_deg) : 0.0;
  out.push_back({0.0, at_nadir});
  for (long z = 1; z < zeniths; ++z)
    for (long a = 0; a < azimuths; ++a) {
      const double azimuth = static_cast<double>(a) * azimuth_step;
      out.push_back({static_cast<double>(z) * zenith_step,
                     rami_frame ? compass_azimuth(azimuth, sun_azimuth_deg) : azimuth});
    }
  return out;
}

}  // namespace landsim::renderer
