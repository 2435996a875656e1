#pragma once
// Wind sway (Weber & Penn 1995, section 4.7) for every tree core, on the finished skeleton:
// at each joint of a stem (the start of each stretch between two cross-sections) the rest of
// the stem turns about the joint's x and y axes by
//   a0 = 4 L (1 - Z) / r_Z,  a1 = speed / 50 a0,  a2 = gust / 50 a0 + a1 / 2   (degrees)
//   b = phase + r_0 / L x time / 15                                          (radians)
//   sway = [a1 sin(b) + a2 sin(0.7 b)] x (stretch length / L)                (degrees)
// with Z the joint's position along the stem (0 at its base, 1 at its tip), r_Z the stem's
// radius there, r_0 its base radius and L its length. The paper divides by nCurveRes, the
// number of equal segments a Weber & Penn stem has: stretch length / L is that for equal
// segments and the same per unit of length for any other spacing of cross-sections. Each
// stem's rotations carry everything beyond them, its children and leaves included; leaves
// flutter besides (docs/SPECIES.md "Wind").
#include <cstdint>

#include "trees/skeleton.h"

namespace landsim::trees {

struct WindState {
  double time = 0.0;   // seconds
  double speed = 0.0;  // the paper's windspeed
  double gust = 0.0;   // the paper's windgust
  // Seeds the stems' sway phases and the leaves' flutter phases; a tree's phase groups
  // differ only here.
  std::uint64_t phase_seed = 0;
  bool active() const { return speed != 0.0 || gust != 0.0; }
};

// The paper's a0 in degrees, uncapped: it is not a turn itself (a1 and a2 scale it by the
// wind, and each joint turns by its share of them).
double sway_amplitude(double length, double z, double radius_z);

// Turns about each axis at the joint at unit position `z` of a stem of `length`, base radius
// `base_radius`, radius `radius_z` there, for a stretch of `stretch` metres after the joint:
// degrees about the joint's x axis and y axis.
struct SwayAngles {
  double x = 0.0, y = 0.0;
};
SwayAngles sway_angles(const WindState& wind, double length, double z, double radius_z,
                       double base_radius, double stretch, double phase_x, double phase_y);

// Fills in what a core left out: each stem above level 0 without a parent hangs from the
// nearest stretch of an earlier stem, each leaf without a stem from the nearest stretch of
// any stem.
void complete_attachments(TreeSkeleton& skeleton);

// Leaf flutter, degrees: leaf `leaf` twists about its petiole's line by
// min(kMaxFlutter, kFlutterPerSpeed x (speed + gust)) x sin(2 pi (f t + phase)), its rate f
// between kFlutterHz and its phase drawn from the wind's phase seed.
double flutter_angle(const WindState& wind, std::size_t leaf);
inline constexpr double kFlutterPerSpeed = 3.0;
inline constexpr double kMaxFlutter = 45.0;
inline constexpr double kFlutterHz[2] = {1.5, 3.0};

// Sways `skeleton` in place (nothing when the wind is calm).
void apply_sway(TreeSkeleton& skeleton, const WindState& wind);

// Bound of a stem's sway summed along it, degrees: each joint turns by at most its share of
// this about each axis, so that no stem folds over in the strongest wind (docs/SPECIES.md
// "Wind"). It binds only in winds beyond the paper's light to moderate range.
inline constexpr double kMaxStemTurn = 90.0;

}  // namespace landsim::trees
