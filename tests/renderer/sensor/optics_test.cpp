// The optics (docs/SENSOR.md "Optics"): the MTF formulas, and a slanted edge through
// apply_optics measured as ISO 12233 measures a camera, against the model's MTF50.
#include "renderer/sensor/optics.h"

#include <gtest/gtest.h>

#include "renderer/atmosphere/sky.h"
#include "renderer/transport/render.h"

#include <cmath>
#include <numbers>
#include <vector>

namespace landsim::renderer {
namespace {

constexpr double kPi = std::numbers::pi;

SensorModel sharp_lens() {
  SensorModel m;
  m.pixel_pitch_um = 2.0;
  m.f_number = 8.0;
  m.blur_sigma_um = 1.0;
  return m;
}

TEST(Optics, TransferFunctionsPinned) {
  const SensorModel m = sharp_lens();
  // Diffraction: cut-off at pitch / (lambda N) = 2 um / (0.55 um x 8) cycles per pixel.
  const double cutoff = 2.0 / (0.55 * 8.0);
  EXPECT_DOUBLE_EQ(diffraction_mtf(0.0, 550.0, m), 1.0);
  EXPECT_NEAR(diffraction_mtf(cutoff * 0.999, 550.0, m), 0.0, 1e-4);
  EXPECT_EQ(diffraction_mtf(cutoff * 1.001, 550.0, m), 0.0);
  const double x = 0.5;
  EXPECT_NEAR(diffraction_mtf(x * cutoff, 550.0, m),
              2.0 / kPi * (std::acos(x) - x * std::sqrt(1.0 - x * x)), 1e-12);
  // Gaussian of sigma 0.5 px; the pixel's sinc.
  EXPECT_NEAR(blur_mtf(0.3, m), std::exp(-2.0 * kPi * kPi * 0.25 * 0.09), 1e-12);
  EXPECT_NEAR(pixel_mtf(0.5), 2.0 / kPi, 1e-12);
  EXPECT_NEAR(pixel_mtf(1.0), 0.0, 1e-12);
  EXPECT_NEAR(system_mtf(mtf50(550.0, m), 550.0, m), 0.5, 1e-9);
  // Longer wavelengths diffract more.
  EXPECT_LT(mtf50(700.0, m), mtf50(450.0, m));
}

TEST(Optics, PreservesAFlatFieldAndTheTotal) {
  const SensorModel m = sharp_lens();
  std::vector<float> flat(80 * 60, 7.0f);
  apply_optics(flat, 80, 60, 550.0, m);
  for (const float v : flat) ASSERT_NEAR(v, 7.0f, 1e-4f);
  // A point in the middle spreads: the image keeps what the Airy pattern puts within its
  // square, between the encircled energy 1 - J0(v)^2 - J1(v)^2 (v = pi r / (lambda N)) of
  // the inscribed and of the circumscribed circle.
  std::vector<float> point(81 * 81, 0.0f);
  point[40 * 81 + 40] = 1000.0f;
  apply_optics(point, 81, 81, 550.0, m);
  double total = 0.0;
  for (const float v : point) total += v;
  const auto encircled = [&](double r_px) {
    const double v = kPi * r_px * m.pixel_pitch_um / (0.55 * m.f_number);
    return 1000.0 *
           (1.0 - std::pow(std::cyl_bessel_j(0.0, v), 2) - std::pow(std::cyl_bessel_j(1.0, v), 2));
  };
  EXPECT_GT(total, encircled(40.5));
  EXPECT_LT(total, encircled(40.5 * std::sqrt(2.0)));
  EXPECT_LT(point[40 * 81 + 40], 500.0f);  // spread: the centre keeps less than half
  EXPECT_NEAR(point[40 * 81 + 41], point[41 * 81 + 40], 1e-3);  // round
}

// A dark-to-bright edge tilted by atan(1/10), each pixel the exact fraction of its square
// on the bright side (what the render's box-filtered samples converge to).
std::vector<float> slanted_edge(int side, double slope) {
  std::vector<float> image(static_cast<std::size_t>(side * side));
  constexpr int kSub = 32;
  for (int y = 0; y < side; ++y)
    for (int x = 0; x < side; ++x) {
      int bright = 0;
      for (int j = 0; j < kSub; ++j)
        for (int i = 0; i < kSub; ++i) {
          const double px = x + (i + 0.5) / kSub, py = y + (j + 0.5) / kSub;
          bright += px > 0.5 * side + slope * (py - 0.5 * side) ? 1 : 0;
        }
      image[static_cast<std::size_t>(y * side + x)] =
          static_cast<float>(10.0 + 90.0 * bright / (kSub * kSub));
    }
  return image;
}

// The slanted-edge MTF (ISO 12233): pixels projected onto the edge's normal and binned at a
// quarter pixel (the edge spread function), differentiated (the line spread function), and
// its Fourier transform at `f`, corrected for the binning's and the difference's own
// transfer functions.
double edge_mtf(const std::vector<float>& image, int side, double slope, double f) {
  constexpr double kBin = 0.25;
  const double norm = std::sqrt(1.0 + slope * slope);
  constexpr int kBins = 96;  // 24 pixels each side of the edge
  std::vector<double> sum(kBins, 0.0);
  std::vector<int> count(kBins, 0);
  for (int y = 8; y < side - 8; ++y)
    for (int x = 0; x < side; ++x) {
      const double px = x + 0.5, py = y + 0.5;
      const double d = (px - 0.5 * side - slope * (py - 0.5 * side)) / norm;
      const int b = static_cast<int>(std::floor(d / kBin)) + kBins / 2;
      if (b < 0 || b >= kBins) continue;
      sum[static_cast<std::size_t>(b)] += image[static_cast<std::size_t>(y * side + x)];
      ++count[static_cast<std::size_t>(b)];
    }
  std::vector<double> esf(kBins);
  for (int b = 0; b < kBins; ++b) esf[b] = sum[b] / std::max(count[b], 1);
  double re = 0.0, im = 0.0, dc = 0.0;
  for (int b = 1; b + 1 < kBins; ++b) {
    const double lsf = (esf[b + 1] - esf[b - 1]) / (2.0 * kBin);
    const double d = (b - kBins / 2 + 0.5) * kBin;
    re += lsf * std::cos(2.0 * kPi * f * d);
    im += lsf * std::sin(2.0 * kPi * f * d);
    dc += lsf;
  }
  const auto sinc = [](double x) { return x == 0.0 ? 1.0 : std::sin(x) / x; };
  const double difference = sinc(2.0 * kPi * f * kBin), binning = sinc(kPi * f * kBin);
  return std::hypot(re, im) / dc / (difference * binning);
}

double measured_mtf50(const std::vector<float>& image, int side, double slope) {
  double lo = 0.02, hi = 0.5;
  for (int i = 0; i < 40; ++i) {
    const double mid = 0.5 * (lo + hi);
    (edge_mtf(image, side, slope, mid) > 0.5 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

TEST(Optics, SlantedEdgeMtf50MatchesTheModel) {
  const SensorModel m = sharp_lens();
  constexpr int kSide = 128;
  constexpr double kSlope = 0.1;
  std::vector<float> image = slanted_edge(kSide, kSlope);
  // Without optics the edge is the pixel's box alone: MTF50 near 0.60 cycles per pixel,
  // beyond Nyquist; the lens brings it far below.
  apply_optics(image, kSide, kSide, 550.0, m);
  const double model = mtf50(550.0, m);
  ASSERT_LT(model, 0.35);
  EXPECT_NEAR(measured_mtf50(image, kSide, kSlope) / model, 1.0, 0.05)
      << measured_mtf50(image, kSide, kSlope) << " against " << model;
}

// A path-traced edge: flat ground, dark west of the line x = 0.1 y and bright east of it (two
// materials meeting exactly on the line), seen straight down through an orthographic camera
// of 0.1 m pixels; its luminance through the optics.
TEST(Optics, RenderedSlantedEdgeMtf50MatchesTheModel) {
  constexpr float kHalf = 100.0f, kSlope = 0.1f;
  Scene s;
  terrain::GroundMesh& g = s.ground.mesh;
  g.vertices = {{-kHalf, -kHalf, 0}, {-kSlope * kHalf, -kHalf, 0}, {kHalf, -kHalf, 0},
                {kHalf, kHalf, 0},   {kSlope * kHalf, kHalf, 0},   {-kHalf, kHalf, 0}};
  g.normals.assign(g.vertices.size(), Vec3f{0, 0, 1});
  g.indices = {0, 1, 4, 0, 4, 5, 1, 2, 3, 1, 3, 4};
  s.ground.albedo = {0.05f, 0.05f, 0.05f};
  s.ground.materials = {GroundMaterial{{0.8f, 0.8f, 0.8f}, false}};
  s.ground.triangle_material = {0, 0, 1, 1};
  s.ground.plain = false;
  s.sun.direction = normalize(Vec3{0.2, -0.3, 0.9});
  s.sun.irradiance = sun_irradiance(s.sky, 64.0, s.sun.angular_radius);
  s.settings.spp = 64;
  View v{"edge", {0.0, 0.0, 50.0}, {0.0, 0.0, 0.0}, 40.0, 128, 128};
  v.lens.projection = Projection::orthographic;
  v.lens.extent_width = v.lens.extent_height = 12.8;
  s.views.push_back(v);
  const Film film = Renderer(s).render(s.views[0], {});
  std::vector<float> image(film.pixel_count());
  for (int y = 0; y < film.height(); ++y)
    for (int x = 0; x < film.width(); ++x)
      image[static_cast<std::size_t>(y * film.width() + x)] = film.luminance(x, y);
  // North up: the line runs from the image's centre to the right going up, x - 64 = -0.1
  // (y - 64) in pixels.
  const SensorModel m = sharp_lens();
  apply_optics(image, 128, 128, 550.0, m);
  const double model = mtf50(550.0, m);
  EXPECT_NEAR(measured_mtf50(image, 128, -kSlope) / model, 1.0, 0.05)
      << measured_mtf50(image, 128, -kSlope) << " against " << model;
}

}  // namespace
}  // namespace landsim::renderer
