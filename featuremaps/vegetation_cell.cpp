#include "featuremaps/vegetation_cell.h"

#include <bit>

namespace landsim::featuremaps {

int VegetationCell::tree_bit_count() const { return std::popcount(tree_bits()); }

std::optional<int> VegetationCell::species_bit() const {
  if (tree_bits() == 0) return std::nullopt;
  return std::countr_zero(tree_bits());
}

}  // namespace landsim::featuremaps
