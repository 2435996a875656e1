#pragma once
// What a view's camera is, as plain data (docs/CAMERAS.md): its projection, the intrinsics
// that go with it, OpenCV's Brown-Conrady lens distortion and a thin lens. renderer/camera.h
// turns it into rays; scenes/ reads it from a scenario's [[views]] table.
#include <cstdint>
#include <optional>
#include <string_view>

namespace landsim::renderer {

enum class Projection : std::uint8_t {
  perspective,          // pinhole: x = X / Z, with K
  orthographic,         // parallel rays across `extent`
  fisheye_equidistant,  // r = f theta
  fisheye_equisolid,    // r = 2 f sin(theta / 2)
  spherical             // equirectangular: 360 degrees across, 180 down
};

std::string_view projection_name(Projection p);
// The projection projection_name names; empty for any other text.
std::optional<Projection> projection_from_name(std::string_view name);

inline bool is_fisheye(Projection p) {
  return p == Projection::fisheye_equidistant || p == Projection::fisheye_equisolid;
}

// OpenCV's radial (k1, k2, k3) and tangential (p1, p2) coefficients, on normalised image
// coordinates x = X / Z, y = Y / Z with y down (cv::projectPoints' model).
struct Distortion {
  double k1 = 0.0, k2 = 0.0, k3 = 0.0, p1 = 0.0, p2 = 0.0;
  bool any() const { return k1 != 0.0 || k2 != 0.0 || k3 != 0.0 || p1 != 0.0 || p2 != 0.0; }
};

struct Lens {
  Projection projection = Projection::perspective;
  // Perspective: fx / fy (non-square pixels; 1 for square ones).
  double fx_over_fy = 1.0;
  // Perspective and fisheye: the principal point's offset from the image centre, pixels,
  // x right, y down.
  double principal_x = 0.0, principal_y = 0.0;
  Distortion distortion{};  // perspective only
  // Orthographic: the width and height the image spans, metres.
  double extent_width = 0.0, extent_height = 0.0;
  // Fisheye: focal length in pixels; rays leave up to half the view's fov from the axis.
  double fisheye_focal = 0.0;
  // Thin lens (perspective only): aperture radius and the distance along the optical axis
  // that is in focus, metres; radius 0 is a pinhole.
  double aperture_radius = 0.0;
  double focus_distance = 0.0;
  // As written in the scenario (for the record in the EXR and manifest); 0: not given.
  double focal_length_mm = 0.0;
  double f_number = 0.0;
  // A region of a larger sensor (perspective): the whole sensor's pixels and the region's
  // top-left corner in them; 0 x 0: the image is the whole sensor. The principal point
  // already holds the region's offset (for the record).
  int sensor_width = 0, sensor_height = 0;
  double region_x0 = 0.0, region_y0 = 0.0;
};

}  // namespace landsim::renderer
