#pragma once
// The 100-float parameter layout of the harmonic core (Hoetzlein 2022): 8 general, 36
// hierarchical (9 per level, levels 0-3; deeper levels use level 3's), 24 arc (4 sections of
// span and bend, levels 0-2; deeper use level 2's), 8 linear wander (angle and interval per
// level), 12 harmonic (frequency, amplitude, phase per level) and 12 semantic (leaves and a
// second part kind). Each entry has its valid range (files outside it are refused) and a
// narrower discovery range (`landsim discover` samples there). docs/HARMONIC.md lists them.
#include <array>
#include <cstddef>
#include <string>

namespace landsim::trees::harmonic {

inline constexpr std::size_t kParameterCount = 100;

enum class Block { general, hierarchy, arc, wander, harmonic, semantic };

struct ParameterSpec {
  const char* name;
  double min, max;                    // valid
  double discover_min, discover_max;  // sampled by `landsim discover`
  bool whole = false;                 // a count: rounded after variation
};

// Where each block starts in the flat array, its entries per row and its rows.
struct BlockShape {
  const char* key;  // the species-file key
  std::size_t offset, per_row, rows;
};

const BlockShape& block_shape(Block block);
const std::array<ParameterSpec, kParameterCount>& parameter_specs();
// "hierarchy[2].branch_angle": the file key, row and name of flat index i.
std::string parameter_label(std::size_t i);

}  // namespace landsim::trees::harmonic
