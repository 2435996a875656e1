#include "renderer/sensor/vignetting.h"

#include <algorithm>
#include <cmath>

#include "renderer/lens_distortion.h"

namespace landsim::renderer {
namespace {

// A rectilinear lens maps the angle theta to rho_d(tan theta) focal lengths from the axis.
// A pixel's irradiance is the pupil's (constant) area, foreshortened by cos(theta), times the
// solid angle per unit image area, sin(theta) / (r dr/dtheta): with rho = tan(theta) that is
// cos^4(theta) rho / (rho_d rho_d'), where rho_d = rho D(rho), D = 1 + k1 rho^2 + ...
double perspective_illumination(const ImageField& f, double x, double y) {
  Normalised n{(x - f.cx) / f.fx, (y - f.cy) / f.fy};
  if (f.distortion.any()) {
    const std::optional<Normalised> u = undistort(f.distortion, n);
    if (!u) return 1.0;  // beyond a fold: the camera sends no ray, the pixel is black
    n = *u;
  }
  const double rho2 = n.x * n.x + n.y * n.y;
  const double cos2 = 1.0 / (1.0 + rho2);
  const Distortion& d = f.distortion;
  const double stretch = 1.0 + rho2 * (d.k1 + rho2 * (d.k2 + rho2 * d.k3));
  const double slope = 1.0 + rho2 * (3.0 * d.k1 + rho2 * (5.0 * d.k2 + rho2 * 7.0 * d.k3));
  return cos2 * cos2 / (stretch * slope);
}

// The same for a fisheye, r = f theta (equidistant): cos(theta) sin(theta) / theta; or
// r = 2 f sin(theta / 2) (equisolid, equal areas for equal solid angles): cos(theta).
double fisheye_illumination(const ImageField& f, double x, double y) {
  const double r = std::hypot((x - f.cx) / f.fx, (y - f.cy) / f.fy);
  if (f.projection == Projection::fisheye_equisolid) {
    if (r >= 2.0) return 1.0;  // outside the image circle: no ray
    return std::cos(2.0 * std::asin(0.5 * r));
  }
  if (r < 1e-9) return 1.0;
  return std::max(0.0, std::cos(r) * std::sin(r) / r);
}

}  // namespace

double natural_illumination(const ImageField& field, double x, double y) {
  switch (field.projection) {
    case Projection::perspective:
      return perspective_illumination(field, x, y);
    case Projection::fisheye_equidistant:
    case Projection::fisheye_equisolid:
      return fisheye_illumination(field, x, y);
    case Projection::orthographic:
    case Projection::spherical:
      return 1.0;
  }
  return 1.0;
}

double lens_illumination(const ImageField& field, const std::array<double, 3>& k, double x,
                         double y) {
  const double r = std::hypot(x - field.cx, y - field.cy) / field.half_diagonal_px;
  const double r2 = r * r;
  return 1.0 + r2 * (k[0] + r2 * (k[1] + r2 * k[2]));
}

double lens_polynomial_minimum(const std::array<double, 3>& k, double r_max) {
  double least = 1.0;
  constexpr int kSteps = 1000;
  for (int i = 0; i <= kSteps; ++i) {
    const double r2 = std::pow(r_max * i / kSteps, 2);
    least = std::min(least, 1.0 + r2 * (k[0] + r2 * (k[1] + r2 * k[2])));
  }
  return least;
}

std::vector<double> vignetting_factors(int width, int height, const ImageField& field,
                                       const VignettingModel& model) {
  if (!model.any()) return {};
  const bool polynomial = model.lens != std::array<double, 3>{0.0, 0.0, 0.0};
  std::vector<double> factors(static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
  for (int j = 0; j < height; ++j) {
    for (int i = 0; i < width; ++i) {
      const double x = i + 0.5, y = j + 0.5;
      double factor = 1.0;
      if (model.natural) factor *= natural_illumination(field, x, y);
      if (polynomial) factor *= lens_illumination(field, model.lens, x, y);
      factors[static_cast<std::size_t>(j) * width + i] = factor;
    }
  }
  return factors;
}

void apply_vignetting(std::vector<float>& plane, const std::vector<double>& factors) {
  for (std::size_t i = 0; i < factors.size(); ++i)
    plane[i] = static_cast<float>(plane[i] * factors[i]);
}

}  // namespace landsim::renderer
