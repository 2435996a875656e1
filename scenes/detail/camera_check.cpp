#include "scenes/detail/camera_check.h"

#include <fmt/format.h>

#include "core/input_warnings.h"

namespace landsim::scenes::detail {

void warn_cameras_below_ground(const Scenario& s, const terrain::ElevationGrid& grid) {
  for (const ViewSettings& v : s.views) {
    const std::optional<double> ground = grid.height(v.position.x, v.position.y);
    if (ground && v.position.z < *ground)
      warn_input(
          fmt::format("{}: [views \"{}\"] position: the camera is {:.1f} m below the "
                      "ground (the terrain is at {:.1f} m there)",
                      v.location, v.name, *ground - v.position.z, *ground));
  }
}

}  // namespace landsim::scenes::detail
