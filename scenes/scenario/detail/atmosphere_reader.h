#pragma once
// Private to scenes/scenario/: reads [atmosphere] (docs/ATMOSPHERE.md "One atmosphere"): the
// standard profile's molecules (Rayleigh scattering, ozone absorption and its column) and the
// aerosol layer ([atmosphere.aerosol]: visibility or optical depth at 550 nm, its profile and
// its optical type), and refuses what would describe the atmosphere a second time: [haze],
// Hosek-Wilkie's turbidity, a sky model of its own, a sun irradiance of its own.
// Include from .cpp files only (toml++ is a heavy header).
#include <toml++/toml.h>

#include <string>

#include "scenes/scenario/scenario.h"

namespace landsim::scenes::detail {

// Reads [atmosphere] into s.haze and s.sky (after [sun], [sky] and [haze] were read); without
// [atmosphere] and without [sky] model = "atmosphere", leaves s as it is.
void read_atmosphere(const toml::table& root, const std::string& file, Scenario& s);

}  // namespace landsim::scenes::detail
