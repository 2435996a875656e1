#pragma once
// Harmonic-core parameters: the 100 floats of layout.h, with typed views of each block.
// Species files give each block as an array (rows of arrays where a block has one row per
// level); the wrong number of values or a value outside its range is refused.
#include <array>
#include <cstdint>
#include <string>
#include <string_view>

#include "trees/harmonic/layout.h"

namespace landsim::params {
class TableReader;
}

namespace landsim::trees::harmonic {

struct LevelParameters {
  int node_spacing;  // steps between nodes
  double node_probability, branch_probability;
  double branch_angle, divergence;  // radians
  int terminal_age;                 // steps a bud of this level lives
  double radius_ratio;              // a child's girth rate over its parent's
  double twist;                     // radians per step about the heading
  double step_scale;                // this level's step over the general step length
};

struct ArcSection {
  int span;     // steps
  double bend;  // radians over the section: positive turns up, negative down
};

struct Parameters {
  std::array<double, kParameterCount> values{};

  double at(Block b, std::size_t row, std::size_t k) const;
  int max_age() const { return static_cast<int>(values[0]); }
  double step_length() const { return values[1]; }
  int levels() const { return static_cast<int>(values[2]); }
  double girth_rate() const { return values[3]; }
  double tip_radius() const { return values[4]; }
  double wander_noise() const { return values[5]; }
  double variation() const { return values[6]; }
  double tropism() const { return values[7] * 3.14159265358979323846 / 180.0; }  // radians/step
  LevelParameters level(int i) const;              // levels beyond 3 use row 3
  std::array<ArcSection, 4> arc(int level) const;  // beyond 2 use row 2
  double wander_angle(int level) const;            // radians
  int wander_interval(int level) const;
  double harmonic_frequency(int level) const;  // radians per step
  double harmonic_amplitude(int level) const;  // radians
  double harmonic_phase(int level) const;      // radians
  double semantic(std::size_t k) const { return values[88 + k]; }
};

// The default layout values: a small broadleaf (every value inside its range).
Parameters default_parameters();

// Reads the core's keys (general, hierarchy, arc, wander, harmonics, semantic) of a species
// file; throws InputError naming file, line, key, index and the expected count or range.
Parameters read_parameters(params::TableReader& root, const std::string& source);

// One individual: every value times (1 + variation * u), u uniform in [-1, 1] from the seed,
// kept in range; counts rounded. Variation 0 returns the values unchanged.
Parameters vary(const Parameters& p, std::uint64_t seed);

// Values uniform between each parameter's discovery bounds (`landsim discover`).
Parameters sample_discovery(std::uint64_t seed);

// The core's keys as species-file TOML (one block per line, rows per level): what
// parse_species_toml reads back to the same values.
std::string format_parameters(const Parameters& p);

}  // namespace landsim::trees::harmonic
