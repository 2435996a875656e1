#pragma once
// Wind sway (Weber & Penn section 4.7): every segment of a stem turns about its x and y axes
// by angles that oscillate with time, wind speed and gusts; each stem has its own phase.
namespace landsim::trees::weber_penn {

struct Wind {
  double time = 0.0;   // seconds
  double speed = 0.0;  // wind speed
  double gust = 0.0;   // gust speed
  bool active() const { return speed != 0.0 || gust != 0.0; }
};

struct SwayAngles {
  double x = 0.0, y = 0.0;  // degrees, per segment
};

// `length`, `offset_ratio` (offset on the parent / parent length, 0 for a trunk),
// `radius_here` (the stem's radius at this segment), `base_radius`, `phase_x/y` (0-2 pi).
SwayAngles sway(const Wind& wind, double length, double offset_ratio, double radius_here,
                double base_radius, int curve_res, double phase_x, double phase_y);

// Upper bound of a0 in degrees: the formula grows without bound as a twig's radius goes to
// zero; beyond half a turn a segment would fold back on itself (docs/SPECIES.md).
inline constexpr double kMaxSwayAmplitude = 180.0;

}  // namespace landsim::trees::weber_penn
