#pragma once
// The one atmosphere's sky by single scattering (docs/ATMOSPHERE.md "One atmosphere",
// "Sampling the atmosphere's sky"): the sun's light scattered once into a direction by the
// plane-parallel medium above a height, unshadowed, by quadrature over heights. What a
// surface draws its sky directions from (a DirectionTable of its luminance), never the sky's
// answer: the radiance along a drawn direction is estimated by the paths themselves.
#include "core/vec3.h"
#include "renderer/atmosphere/medium.h"
#include "renderer/spectra/spectrum.h"

namespace landsim::renderer {

// Single-scattered radiance arriving at height z from the upward direction d (zero for d
// below the horizon), under a sun of irradiance `sun` (per bin, across its beam) toward
// `sun_direction`.
Spectrum single_scattered_sky(const Medium& medium, const Spectrum& sun, const Vec3f& sun_direction,
                              double z, const Vec3f& d);

}  // namespace landsim::renderer
