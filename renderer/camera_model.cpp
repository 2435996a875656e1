#include "renderer/camera_model.h"

namespace landsim::renderer {

std::string_view projection_name(Projection p) {
  switch (p) {
    case Projection::perspective:
      return "perspective";
    case Projection::orthographic:
      return "orthographic";
    case Projection::fisheye_equidistant:
      return "fisheye equidistant";
    case Projection::fisheye_equisolid:
      return "fisheye equisolid";
    case Projection::spherical:
      return "spherical";
  }
  return "perspective";
}

std::optional<Projection> projection_from_name(std::string_view name) {
  for (const Projection p :
       {Projection::perspective, Projection::orthographic, Projection::fisheye_equidistant,
        Projection::fisheye_equisolid, Projection::spherical})
    if (projection_name(p) == name) return p;
  return std::nullopt;
}

}  // namespace landsim::renderer
