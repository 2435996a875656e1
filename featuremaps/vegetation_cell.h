#pragma once
// One cell of a vegetation feature map (Weber & Penn section 6): a 16-bit value whose
// bits 0-13 select tree species and bits 14-15 one of three grass types (0 = no grass).
#include <cstdint>
#include <optional>

namespace landsim::featuremaps {

inline constexpr int kTreeBits = 14;
inline constexpr std::uint16_t kTreeMask = (1u << kTreeBits) - 1u;

struct VegetationCell {
  std::uint16_t raw = 0;

  // Grass type 1..3, or 0 for none.
  int grass_type() const { return raw >> kTreeBits; }
  std::uint16_t tree_bits() const { return raw & kTreeMask; }
  // Number of tree species bits set (species are meant to be mutually exclusive).
  int tree_bit_count() const;
  // The species bit that applies: the lowest one set, or none.
  std::optional<int> species_bit() const;
};

}  // namespace landsim::featuremaps
