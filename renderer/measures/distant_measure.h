#pragma once
// A distant measure (docs/CANOPIES.md "Measures"): what a sensor infinitely far away sees of a
// periodic cell (renderer::PeriodicCell) in each of a list of directions: the radiance leaving
// the whole cell towards it, averaged over the cell, and the bidirectional reflectance factor
// BRF = pi L / (E cos theta_sun) with E the sun's irradiance normal to its beam, each with its
// Monte Carlo standard error. It stands beside the camera: the same path tracer, rays started
// uniformly over the cell's top instead of through a lens.
#include <cstdint>
#include <optional>
#include <vector>

#include "renderer/scene.h"

namespace landsim::renderer {

// Towards the sensor: zenith 0-90 degrees, azimuth clockwise from north (+y), degrees.
struct DistantDirection {
  double zenith_deg = 0.0;
  double azimuth_deg = 0.0;
};

struct DistantValue {
  double mean = 0.0;
  double standard_error = 0.0;
};

// The mean of n samples whose sum and sum of squares are given, and its standard error, both
// times `scale` (the measures' one estimator).
DistantValue mean_with_error(double sum, double squares, double n, double scale = 1.0);

// The height rays from infinitely far away (the sensor's, the sun's) start at: the cell's
// top, or the haze's where it reaches higher (renderer/atmosphere/medium.h).
double entry_height(const Scene& scene, const PeriodicCell& cell);

struct DistantResult {
  DistantDirection direction;
  DistantValue radiance;  // luminance, cd/m2 (the image's Y)
  DistantValue brf;       // of the luminance: every wavelength's where the optics are grey
  std::vector<DistantValue> band_brf;  // of each of the scene's bands, in order
  std::uint64_t paths = 0;             // traced for it
};

// Below this BRF --target-se bounds the error absolutely: at 0.5%, to 5 x 10^-5.
inline constexpr double kLeastAimedBrf = 0.01;

struct DistantMeasureOptions {
  std::uint64_t samples = 4096;  // paths per direction (rounded up to whole batches)
  // Independently scrambled Sobol sequences the paths are drawn in (randomised quasi-Monte
  // Carlo): within one, the paths' points are stratified over the cell and every later pair
  // of dimensions; the standard error comes from the spread of the batches' means.
  int batches = 32;
  // When above 0: more paths (at least a quarter more a round, up to max_samples) until the
  // BRF's standard error is at most this fraction of it, or of kLeastAimedBrf for a darker
  // direction (a BRF near 0 is bounded absolutely, not chased to max_samples); `samples` is
  // then where each direction starts.
  double target_relative_error = 0.0;
  std::uint64_t max_samples = std::uint64_t{1} << 26;
  // The band whose BRF the target bounds (a monochromatic run's wavelength); -1: the
  // luminance's.
  int target_band = -1;
  std::uint64_t seed = 1;
  int threads = 0;  // 0: every core
  // At the bottom of the atmosphere (docs/CANOPIES.md "Measures"): rays start just above the
  // cell instead of above the medium, and each BRF becomes the HDRF, the radiance over a white
  // Lambertian reference's under the same light: pi L / E, E the downwelling irradiance there
  // (renderer/atmosphere/downwelling.h, from the same medium over the plain's albedo).
  bool bottom_of_atmosphere = false;
  // Where the rays start, uniformly over x0-x1, y0-y1 at height `top`; empty: the scene's
  // periodic cell. A scene that is not periodic (the cell copied around itself) is measured
  // over a region of it.
  std::optional<PeriodicCell> region;
};

// Throws std::invalid_argument when neither the scene nor the options give a cell, or the sun
// is below the horizon. The same options give the same bits on any thread count.
std::vector<DistantResult> measure_distant(const Scene& scene,
                                           const std::vector<DistantDirection>& directions,
                                           const DistantMeasureOptions& options);

// The cell's bi-hemispherical reflectance at the bottom of the atmosphere under the scene's own
// sun and sky (RAMI4ATM's BHR): the upward flux just above the cell (pi x the mean radiance
// of cosine-distributed views down) over the downwelling irradiance there; in `brf` and
// `band_brf` (direction zenith 0), the upward radiance's mean in `radiance`.
DistantResult measure_bhr(const Scene& scene, const DistantMeasureOptions& options);

// RAMI's principal plane: view zeniths -75 to 75 every 2 degrees, negative ones on the sun's
// side (azimuth of the sun), positive ones opposite.
std::vector<DistantDirection> principal_plane(double sun_azimuth_deg);

}  // namespace landsim::renderer
