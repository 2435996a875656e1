#pragma once
// The one atmosphere for renderers that light a scene by a sun and a sky at the ground: the
// POV-Ray export and landsim's POV-comparable tracer (docs/CROSSCHECK.md). A scene under
// [atmosphere] becomes the sun's beam at the lowest ground, a gradient sky whose zenith and
// horizon colours are the single-scattered sky's there, scaled so that it gives the diffuse
// irradiance the paths find there, and a uniform fog of the medium's extinction at 550 nm
// there. Any other scene is returned as it is.
#include "renderer/scene.h"

namespace landsim::renderer {

Scene ground_level_equivalent(const Scene& scene);

}  // namespace landsim::renderer
