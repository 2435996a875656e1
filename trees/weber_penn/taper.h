#pragma once
// Stem radius along a stem (Weber & Penn section 4.4): nTaper 0-1 a cone of that strength,
// 1-2 towards a spherical end, 2-3 periodic tapering (a chain of spheres); Flare widens the
// trunk's base.
namespace landsim::trees::weber_penn {

// Radius at distance `z` from the stem base, for a stem of `length` and base radius
// `radius`. `flare` is applied when non-zero (pass 0 for every stem but the trunk).
double stem_radius(double z, double length, double radius, double taper, double flare);

}  // namespace landsim::trees::weber_penn
