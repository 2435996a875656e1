#pragma once
// A landsim view as a POV-Ray 3.7 camera block (docs/CAMERAS.md "POV-Ray"), in the export's
// frame (x east, y up, z north): explicit direction, right and up vectors (no look_at), so a
// roll, a given up vector and a principal point carry over exactly. Perspective,
// orthographic, equidistant fisheye and spherical views have a POV-Ray camera; what POV-Ray
// cannot show (lens distortion, depth of field, an equisolid fisheye, a fisheye's principal
// point) is listed so the export can say so.
#include <string>
#include <vector>

#include "renderer/scene.h"

namespace landsim::exporters {

struct PovView {
  std::string camera;                // "camera { ... }"
  std::vector<std::string> unshown;  // what the block leaves out, one sentence each
};

PovView pov_view(const renderer::View& view);

}  // namespace landsim::exporters
