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

}  // namespace landsim::renderer
