#pragma once
// Harmonic-core parameters: the 100 floats of layout.h, with typed views of each block.
// Species files give each block as an array (rows of arrays where a block has one row per
// level); the wrong number of values or a value outside its range is refused.
#include <algorithm>
#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

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

// Beyond the 100 floats (the paper: "each additional tree part adds 14 parameters", and its
// appendix's terms per level, which its 12 harmonic floats cannot hold):

// A further harmonic term of one level, summed with the layout's row for that level.
struct HarmonicTerm {
  int level = 0;           // 0-3 (deeper levels use 3's)
  double frequency = 0.0;  // radians per step
  double amplitude = 0.0;  // radians
  double phase = 0.0;      // radians
};

// Internode growth (the paper's section 2.3: "internodes begin at a small size and then all
// internodes in the tree are grown simultaneously on each time step"): an internode is
// `initial` of its full length when laid down and reaches it `steps` steps later.
struct Elongation {
  double initial = 1.0;
  int steps = 0;  // 0: full length at once
  double factor(int age) const {
    return steps <= 0 ? 1.0 : initial + (1.0 - initial) * std::min(1.0, double(age) / steps);
  }
};

// A semantic part beyond the layout's leaves and seed balls or cones: flowers (petals in the
// species' flower colour), thorns (bark cones) and auxiliary buds (small bark ovoids in the
// node's axil).
enum class PartKind { flower, thorn, bud };

struct PartSettings {
  PartKind kind = PartKind::thorn;
  int spacing = 2;        // steps between chances (ignored at_nodes)
  bool at_nodes = false;  // one chance at every node instead
  double probability = 1.0;
  double size = 0.01;  // metres: thorn length, bud length, flower diameter
  int level = 0;       // lowest level that carries it
  double angle = 1.0;  // radians from the shoot's heading
  int petals = 5;      // flowers
};

struct Parameters {
  std::array<double, kParameterCount> values{};
  std::vector<HarmonicTerm> terms;
  Elongation elongation;
  std::vector<PartSettings> parts;

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
  // H at a bud's age on `level`: the layout's term plus the level's further terms.
  double harmonic_turn(int level, int age) const;
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
