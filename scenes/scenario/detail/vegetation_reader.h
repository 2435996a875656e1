#pragma once
// Private to scenes/scenario/: reads what grows and what sways it: [featuremaps], [[species]],
// [[grass]] (each with its cover) and [wind]; files resolved and checked to exist.
// Include from .cpp files only (toml++ is a heavy header).
#include <toml++/toml.h>

#include <string>

#include "scenes/scenario/scenario.h"

namespace landsim::scenes::detail {

// [featuremaps]; none when the scenario has none.
std::optional<FeatureMapSettings> read_featuremaps(const toml::table& root, const std::string& file,
                                                   const std::string& base_dir);
std::vector<SpeciesSettings> read_species(const toml::table& root, const std::string& file,
                                          const std::string& base_dir);
std::vector<GrassSettings> read_grass(const toml::table& root, const std::string& file);
WindSettings read_wind(const toml::table& t, const std::string& file);

}  // namespace landsim::scenes::detail
