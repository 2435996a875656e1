#pragma once
// The measured-growth core's entry: the tree at an age (clamped to the data's range).
#include <cstdint>

#include "trees/measured_growth/tree_at_age.h"

namespace landsim::trees::measured_growth {

// `age` < 0: the species' age. Ages outside [0, max_age] are clamped, with a warning.
TreeSkeleton generate_skeleton(const Parameters& p, std::uint64_t seed, double age = -1.0,
                               TreeAtAge* tree = nullptr);

// The parameters of the tree of `seed`: its allometry the equations times its draw from the
// database's scatter (allometry.h `individual`). generate_skeleton grows these.
Parameters tree_parameters(const Parameters& p, std::uint64_t seed);

// Clamps an age to [0, max_age]; warns (spdlog) when it had to.
double clamp_age(const Parameters& p, double age);

}  // namespace landsim::trees::measured_growth
