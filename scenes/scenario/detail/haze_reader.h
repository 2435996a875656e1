#pragma once
// Private to scenes/scenario/: reads [haze] (docs/ATMOSPHERE.md): visibility or a plane-parallel
// layer, the aerosol's albedo, Angstrom exponent and phase function, the air, and how the
// haze's further light is found.
// Include from .cpp files only (toml++ is a heavy header).
#include <toml++/toml.h>

#include <string>

#include "scenes/scenario/scenario.h"

namespace landsim::params {
class TableReader;
}

namespace landsim::scenes::detail {

// An aerosol's optical type, as [haze] and [atmosphere.aerosol] give it: the single-scattering
// albedo (or colour) and the phase function.
void read_aerosol_optics(params::TableReader& r, renderer::Haze& h);

// [haze]; a haze that is not enabled when the scenario has none.
renderer::Haze read_haze(const toml::table& root, const std::string& file);

}  // namespace landsim::scenes::detail
