#pragma once
// OpenCV's Brown-Conrady lens distortion (cv::projectPoints, docs/CAMERAS.md) on normalised
// image coordinates (x = X / Z, y = Y / Z, y down): the forward map, its inverse for rays,
// and the check that it does not fold the frame.
#include <optional>

#include "renderer/camera_model.h"

namespace landsim::renderer {

struct Normalised {
  double x = 0.0, y = 0.0;
};

// Where an undistorted point lands: x'' = x (1 + k1 r^2 + k2 r^4 + k3 r^6) + 2 p1 x y +
// p2 (r^2 + 2 x^2), y'' likewise with p1 and p2 exchanged.
Normalised distort(const Distortion& d, Normalised u);

// The undistorted point that lands on `distorted` (Newton's method on the forward map);
// empty when it does not converge (beyond a fold).
std::optional<Normalised> undistort(const Distortion& d, Normalised distorted);

// Whether the radial part of the map rises monotonically from the centre until it passes
// radius `frame_radius` (the distorted radius of the frame's farthest corner): a fold
// inside the frame would give two scene directions one pixel.
bool unfolded_within(const Distortion& d, double frame_radius);

}  // namespace landsim::renderer
