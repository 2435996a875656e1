#pragma once
// Building a vegetation feature map from a land-cover class raster: each class maps to tree
// species bits with fractions (a cell takes one of them, or none, at random by those
// fractions) and a grass type.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "featuremaps/vegetation_map.h"
#include "terrain/elevation_grid.h"

namespace landsim::featuremaps {

struct SpeciesShare {
  int bit = 0;
  double fraction = 1.0;  // of the class's cells
};

struct ClassRule {
  int value = 0;
  std::vector<SpeciesShare> species;  // fractions sum to at most 1; the rest has no tree
  int grass = 0;                      // 0 none, 1-3
};

struct ClassMapping {
  std::string source;
  std::vector<ClassRule> rules;
};

// Reads a mapping TOML file ([[class]] tables, see docs/SCENARIO.md). Throws InputError.
ClassMapping load_class_mapping(const std::string& path);
// The same from text already read; `path` names it in messages.
ClassMapping parse_class_mapping(std::string_view text, const std::string& path);

// Same grid and placement as `classes` (read as numbers; nodata and unmapped classes get no
// vegetation). The choice per cell depends only on `seed` and the cell.
VegetationMap build_vegetation_map(const terrain::ElevationGrid& classes,
                                   const ClassMapping& mapping, std::uint64_t seed);

}  // namespace landsim::featuremaps
