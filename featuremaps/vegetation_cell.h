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
  // Number of tree species bits set (several: a mixed stand, each species placed by its own
  // density).
  int tree_bit_count() const;
  bool has_tree_bit(int bit) const { return bit >= 0 && bit < kTreeBits && ((raw >> bit) & 1u); }
  // The lowest species bit set, or none (what a one-species cell selects).
  std::optional<int> species_bit() const;
};

}  // namespace landsim::featuremaps
