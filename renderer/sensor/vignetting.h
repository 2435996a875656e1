#pragma once
// Vignetting (docs/SENSOR.md "Vignetting"): how much of the on-axis irradiance the lens
// delivers to each pixel of a uniformly bright scene. Two factors, each optional:
// - natural: the ideal lens's fall-off for its own projection, from the pupil seen obliquely
//   and the solid angle a pixel sees (cos^4 for a rectilinear lens);
// - lens: a measured lens's own polynomial in the radius, lensfun's "pa" model,
//   1 + k1 r^2 + k2 r^4 + k3 r^6 with r = 1 at the whole sensor's corner.
// The sensor multiplies each channel's photon radiance by their product before exposure.
#include <array>
#include <vector>

#include "renderer/camera_model.h"

namespace landsim::renderer {

// What vignetting needs of a view's camera, in landsim's pixel coordinates (pixel (i, j)'s
// centre at i + 0.5, j + 0.5).
struct ImageField {
  Projection projection = Projection::perspective;
  double fx = 0.0, fy = 0.0;      // focal lengths in pixels (perspective, fisheye)
  double cx = 0.0, cy = 0.0;      // where the optical axis meets the image
  Distortion distortion{};        // perspective
  double half_diagonal_px = 0.0;  // of the whole sensor (a region's sensor, not the region)
};

struct VignettingModel {
  bool natural = false;
  std::array<double, 3> lens{0.0, 0.0, 0.0};  // k1, k2, k3
  bool any() const { return natural || lens != std::array<double, 3>{0.0, 0.0, 0.0}; }
};

// The ideal lens's relative illumination at image point (x, y): 1 on the axis.
// Perspective: cos^4(theta) x rho / (rho_d drho_d/drho), rho = tan(theta) the undistorted and
// rho_d the distorted radius (Brown-Conrady's radial terms; 1 without distortion).
// Equidistant fisheye: cos(theta) sin(theta) / theta. Equisolid: cos(theta).
// Orthographic (telecentric) and spherical (no single lens): 1.
double natural_illumination(const ImageField& field, double x, double y);

// The lens polynomial at image point (x, y): r = distance from (cx, cy) / half_diagonal_px.
double lens_illumination(const ImageField& field, const std::array<double, 3>& k, double x,
                         double y);

// The smallest value of 1 + k1 r^2 + k2 r^4 + k3 r^6 for r in [0, r_max] (sampled finely):
// a polynomial that reaches 0 or below inside the frame is not a lens's.
double lens_polynomial_minimum(const std::array<double, 3>& k, double r_max);

// Both factors at each pixel's centre, row-major; empty when the model has none. Computed
// once an image: every channel's plane takes the same.
std::vector<double> vignetting_factors(int width, int height, const ImageField& field,
                                       const VignettingModel& model);
// Multiplies `plane` by `factors` (nothing when they are empty).
void apply_vignetting(std::vector<float>& plane, const std::vector<double>& factors);

}  // namespace landsim::renderer
