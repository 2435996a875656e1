#pragma once
// ShapeRatio (Weber & Penn section 4.3): the tree's silhouette as a function of the
// position `ratio` (0 at the top of the crown, 1 at its base), shapes 0-8.
namespace landsim::trees::weber_penn {

enum Shape : int {
  kConical = 0,
  kSpherical = 1,
  kHemispherical = 2,
  kCylindrical = 3,
  kTaperedCylindrical = 4,
  kFlame = 5,
  kInverseConical = 6,
  kTendFlame = 7,
  kEnvelope = 8,
};

struct Envelope {
  double width = 0.5;       // PruneWidth
  double peak = 0.5;        // PruneWidthPeak
  double power_low = 0.5;   // PrunePowerLow: below the peak
  double power_high = 0.5;  // PrunePowerHigh: above the peak
};

// Shape 8 is the pruning envelope. As printed, its lower branch divides by
// (1 - PruneWidthPeak), which jumps at the peak; we divide by PruneWidthPeak so that both
// branches reach 1 there (docs/SPECIES.md, "Errata").
double shape_ratio(int shape, double ratio, const Envelope& envelope = {});

}  // namespace landsim::trees::weber_penn
