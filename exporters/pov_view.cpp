#include "exporters/pov_view.h"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "renderer/camera.h"

namespace landsim::exporters {
namespace {

using renderer::Projection;

// (x, y, z) -> <x, z, y>: POV-Ray's y is up (pov_export.h).
std::string pov(const Vec3& v) { return fmt::format("<{:.9g}, {:.9g}, {:.9g}>", v.x, v.z, v.y); }

std::string perspective(const renderer::View& v, const renderer::CameraBasis& b) {
  const std::array<double, 9> k = renderer::Camera(v).intrinsics();
  const double fx = k[0], fy = k[4];
  // POV-Ray's ray through (x0, y0) in [-0.5, 0.5]^2 is direction + x0 right + y0 up: the
  // principal point shifts the direction, the focal lengths scale right and up.
  const Vec3 direction =
      b.forward - (v.lens.principal_x / fx) * b.right + (v.lens.principal_y / fy) * b.up;
  return fmt::format("camera {{ perspective location {} direction {} right {} up {} }}",
                     pov(v.position), pov(direction), pov(b.right * (v.width / fx)),
                     pov(b.up * (v.height / fy)));
}

}  // namespace

PovView pov_view(const renderer::View& v) {
  const renderer::CameraBasis b = renderer::camera_basis(v);
  const renderer::Lens& l = v.lens;
  PovView out;
  switch (l.projection) {
    case Projection::perspective:
      out.camera = perspective(v, b);
      if (l.distortion.any())
        out.unshown.push_back("lens distortion (POV-Ray's perspective camera has none)");
      if (l.aperture_radius > 0.0) out.unshown.push_back("depth of field (written as a pinhole)");
      break;
    case Projection::orthographic:
      out.camera = fmt::format("camera {{ orthographic location {} direction {} right {} up {} }}",
                               pov(v.position), pov(b.forward), pov(b.right * l.extent_width),
                               pov(b.up * l.extent_height));
      break;
    case Projection::fisheye_equidistant:
    case Projection::fisheye_equisolid: {
      // POV-Ray's fisheye is equidistant, its circle's radius 1 / |right| of half the width.
      const double half = 0.5 * v.fov_y_deg * std::numbers::pi / 180.0;
      const double circle = 2.0 * l.fisheye_focal * half;
      out.camera =
          fmt::format("camera {{ fisheye location {} direction {} right {} up {} angle {:.9g} }}",
                      pov(v.position), pov(b.forward), pov(b.right * (v.width / circle)),
                      pov(b.up * (v.height / circle)), v.fov_y_deg);
      if (l.projection == Projection::fisheye_equisolid)
        out.unshown.push_back(
            "the equisolid mapping (POV-Ray's fisheye is equidistant; written as one of the same "
            "angle)");
      if (l.principal_x != 0.0 || l.principal_y != 0.0)
        out.unshown.push_back("the fisheye's principal point offset (POV-Ray centres its circle)");
      break;
    }
    case Projection::spherical:
      out.camera = fmt::format(
          "camera {{ spherical location {} direction {} right {} up {} angle 360 180 }}",
          pov(v.position), pov(b.forward), pov(b.right), pov(b.up));
      break;
  }
  return out;
}

}  // namespace landsim::exporters
