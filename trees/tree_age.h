#pragma once
// A tree's age for the cores whose species files describe one grown tree rather than a
// growth history in years (docs/SPECIES.md "Age"): Weber & Penn, graph paths, self-organising
// and harmonic. The file's tree is `mature` years old; a younger one is drawn from the
// height-age curve (a normalised Chapman-Richards curve) as each core grows: Weber & Penn
// and graph paths scale their size and drop their last levels, the self-organising and
// harmonic cores stop their growth early (the younger tree is part of the older).
// Measured growth takes ages in years itself.
namespace landsim::trees {

struct AgeCurve {
  double mature = -1.0;  // years: the age of the file's tree; < 0: the core's default
  // Chapman-Richards H(t) ~ (1 - exp(-kappa t / mature))^shape, normalised to 1 at mature.
  double kappa = 2.5;
  double shape = 1.5;
};

// Default mature age of the file's tree when the species does not say (years).
inline constexpr double kDefaultMatureAge = 30.0;

// H(age) / H(mature), 0 at age 0, 1 at mature; `age` clamped to [0, mature].
double size_fraction(const AgeCurve& curve, double age);

// The levels (orders of branching) a tree of `levels` at maturity has at `age`:
// ceil(levels * size_fraction), at least 2 (or `levels` if fewer).
int levels_at(const AgeCurve& curve, double age, int levels);

// Growth steps (of `steps` at maturity) taken by `age`: round(steps * age / mature).
int steps_at(const AgeCurve& curve, double age, int steps);

// The least age drawn: a year (below it a tree drawn by scaling would shrink towards
// nothing), or the mature age if that is less.
double youngest_age(const AgeCurve& curve);
// `age` within [youngest_age, mature].
double clamped_age(const AgeCurve& curve, double age);
// The same, with a warning naming the species when it was not within.
double clamp_age(const AgeCurve& curve, double age, const char* species);

}  // namespace landsim::trees
