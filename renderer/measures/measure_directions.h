#pragma once
// The directions a distant measure is asked for beyond RAMI's principal plane
// (docs/CANOPIES.md "Measures"): RAMI's azimuth frame beside the compass's, and the
// zenith/azimuth hemisphere grid DART and LESS write.
#include <vector>

#include "renderer/measures/distant_measure.h"

namespace landsim::renderer {

// RAMI's azimuth frame (the sun's azimuth 0, counter-clockwise seen from above) from the
// compass's (clockwise from north, landsim's), and back; degrees in [0, 360).
double rami_relative_azimuth(double compass_azimuth_deg, double sun_azimuth_deg);
double compass_azimuth(double rami_relative_azimuth_deg, double sun_azimuth_deg);

// Zenith 0 once, then every `zenith_step` degrees below 90, each at every `azimuth_step` from
// 0 (in the compass frame, or RAMI's when `rami_frame`); directions in the compass frame.
// Steps in (0, 90] and (0, 360]; at most kMostGridDirections directions (InputError naming
// --hemisphere otherwise).
inline constexpr int kMostGridDirections = 20000;
std::vector<DistantDirection> hemisphere_grid(double zenith_step, double azimuth_step,
                                              double sun_azimuth_deg, bool rami_frame);

}  // namespace landsim::renderer
