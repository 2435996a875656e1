#pragma once
// POV-Ray export: a scene.pov that POV-Ray 3.7 renders without edits, and meshes.inc with
// every tree prototype once (#declare'd mesh2), instanced with matrices. landsim is z-up and
// right-handed, POV-Ray y-up and left-handed: (x, y, z) -> <x, z, y> swaps two axes, which
// changes the handedness without mirroring the image. Identifiers are generated (LS_...);
// nothing from a scenario or species file is written except sanitised comments.
#include <filesystem>
#include <string>

#include "renderer/atmosphere/sky.h"
#include "renderer/scene.h"

namespace landsim::exporters {

struct PovExportOptions {
  // Light as landsim's POV-comparable mode renders it: the sun (irradiance / pi, POV's
  // diffuse has no 1/pi) with shadows plus an unoccluded ambient of the sky's horizontal
  // irradiance / pi, no interreflection; haze as uniform fog of the given colour.
  Vec3f ambient_irradiance{};
  Vec3f fog_colour{};
  Vec3f sky_zenith{};
  Vec3f sky_horizon{};
  // The default of the file's LS_Exposure, which multiplies every light: landsim's units are
  // cd/m2 and lux, POV-Ray's output is what it computes.
  double exposure_gain = 1.0;
};

// The default of the export's LS_Exposure: the scene's fixed exposure, or one that renders a
// white horizontal surface in the sun and sky's light as white: an incident-light meter's
// choice, since POV-Ray cannot meter the image it has not yet made (docs/ATMOSPHERE.md
// "Exposure").
double pov_exposure_gain(const renderer::Scene& scene, const renderer::SkyModel& sky);

// Writes `dir`/scene.pov and `dir`/meshes.inc for `view`. Declaring LS_Mask=1 on the POV-Ray
// command line renders flat class colours instead (ground red, bark green, leaves blue, scene
// objects yellow, sky black) for coverage comparison.
void export_pov(const renderer::Scene& scene, const renderer::View& view,
                const std::filesystem::path& dir, const PovExportOptions& options);

// Keeps letters, digits, space, '_', '-' and '.'; anything else (quotes, '#', newlines)
// becomes '_'. For text written into POV-Ray comments.
std::string sanitize_for_pov(const std::string& text);

}  // namespace landsim::exporters
