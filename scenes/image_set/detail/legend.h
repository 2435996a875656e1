#pragma once
// Private to scenes/: the legend of an image set's layers (docs/OUTPUTS.md "Legend"): what
// every id in the object, species, instance, target and lod layers names, and each layer's
// "none" value; in manifest.json and in every EXR (landsim/legend).
#include <nlohmann/json_fwd.hpp>

#include "scenes/scenario/scenario.h"

namespace landsim::scenes::detail {

nlohmann::json legend(const Scenario& s);

}  // namespace landsim::scenes::detail
