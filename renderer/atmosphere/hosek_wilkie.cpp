#include "renderer/atmosphere/hosek_wilkie.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "renderer/atmosphere/hosek_wilkie_tables.h"
#include "renderer/spectra/colour_matching.h"

namespace landsim::renderer {
namespace {

using Tables = HosekWilkieTables;
constexpr double kHalfPi = 0.5 * std::numbers::pi;

// The quintic Bezier through six control points spaced `stride` apart, at t in [0, 1].
double bezier5(const double* p, int stride, double t) {
  const double s = 1.0 - t;
  const double b[6] = {s * s * s * s * s,        5.0 * s * s * s * s * t, 10.0 * s * s * s * t * t,
                       10.0 * s * s * t * t * t, 5.0 * s * t * t * t * t, t * t * t * t * t};
  double sum = 0.0;
  for (int i = 0; i < 6; ++i) sum += b[i] * p[i * stride];
  return sum;
}

// The two integer turbidities around `turbidity` (1-10) and the weight of the upper one;
// the release interpolates linearly between them.
struct TurbidityPair {
  int lower = 0, upper = 0;  // table indices, turbidity - 1
  double weight = 0.0;
};
TurbidityPair turbidity_pair(double turbidity) {
  const double t = std::clamp(turbidity, 1.0, 10.0);
  const int lower = std::min(static_cast<int>(t), 10);
  return {lower - 1, std::min(lower, 9), t - lower};
}

// Solar elevation's Bezier parameter: the control points are spaced in its cube root, which
// crowds them toward the horizon where the sky changes fastest.
double elevation_parameter(double elevation) {
  return std::cbrt(std::clamp(elevation, 0.0, kHalfPi) / kHalfPi);
}

}  // namespace

HosekWilkieSky::HosekWilkieSky(double elevation, double turbidity, const Vec3& albedo)
    : HosekWilkieSky(elevation, turbidity,
                     std::array<double, 3>{albedo.x, albedo.y, albedo.z}.data(), 3, false) {}

HosekWilkieSky HosekWilkieSky::spectral(double elevation, double turbidity,
                                        const std::array<double, 11>& albedo) {
  return {elevation, turbidity, albedo.data(), Tables::kWavelengths, true};
}

HosekWilkieSky::HosekWilkieSky(double elevation, double turbidity, const double* albedo,
                               int channels, bool spectral)
    : parameters_(static_cast<std::size_t>(channels)),
      overall_(static_cast<std::size_t>(channels)) {
  const Tables& t = hosek_wilkie_tables();
  const double x = elevation_parameter(elevation);
  const TurbidityPair tp = turbidity_pair(turbidity);
  for (int c = 0; c < channels; ++c) {
    const double a = std::clamp(albedo[c], 0.0, 1.0);
    // Parameter p of one table (albedo, turbidity): the Bezier over its control points.
    const auto config = [&](int alb, int turb, int p) {
      return bezier5(t.control_points(c, alb, turb, spectral) + p, Tables::kParameters, x);
    };
    const auto blended = [&](auto&& value) {
      const double low = (1.0 - a) * value(0, tp.lower) + a * value(1, tp.lower);
      const double high = (1.0 - a) * value(0, tp.upper) + a * value(1, tp.upper);
      return (1.0 - tp.weight) * low + tp.weight * high;
    };
    for (int p = 0; p < Tables::kParameters; ++p)
      parameters_[static_cast<std::size_t>(c)][static_cast<std::size_t>(p)] =
          blended([&](int alb, int turb) { return config(alb, turb, p); });
    overall_[static_cast<std::size_t>(c)] = blended([&](int alb, int turb) {
      return bezier5(t.radiance_points(c, alb, turb, spectral), 1, x);
    });
    // The RGB tables integrate spectral radiance against the colour-matching functions
    // without the luminous efficacy: 683 lm/W makes Y luminance in cd/m2
    // (data/sky/PROVENANCE.md). The spectral ones are W m^-2 sr^-1 nm^-1 as they stand.
    if (!spectral) overall_[static_cast<std::size_t>(c)] *= kLumensPerWatt;
  }
}

Vec3 HosekWilkieSky::radiance_cos(double cos_theta, double cos_gamma) const {
  double out[Tables::kWavelengths];
  channels_cos(cos_theta, cos_gamma, out);
  return {out[0], out[1], out[2]};
}

void HosekWilkieSky::channels_cos(double cos_theta_in, double cos_gamma_in, double* out) const {
  const double cos_theta = std::clamp(cos_theta_in, 0.0, 1.0);
  const double cos_gamma = std::clamp(cos_gamma_in, -1.0, 1.0);
  const double gamma = std::acos(cos_gamma);
  const double sqrt_cos_theta = std::sqrt(cos_theta);
  for (std::size_t c = 0; c < overall_.size(); ++c) {
    // The extended Perez formula of the 2012 paper (its Mie term chi(H, gamma) and the
    // zenith term I sqrt(cos theta) added to Perez), parameters in file order.
    const auto& k = parameters_[c];
    const double a = k[0], b = k[1], cc = k[2], d = k[3], e = k[4], f = k[5], g = k[6], i = k[7],
                 h = k[8];
    // x^1.5 as x sqrt(x): pow cost 4% of a render once the sky had 11 channels.
    const double base = 1.0 + h * h - 2.0 * h * cos_gamma;
    const double mie = (1.0 + cos_gamma * cos_gamma) / (base * std::sqrt(base));
    const double zenith_term = 1.0 + a * std::exp(b / (cos_theta + 0.01));
    out[c] =
        zenith_term *
        (cc + d * std::exp(e * gamma) + f * cos_gamma * cos_gamma + g * mie + i * sqrt_cos_theta) *
        overall_[c];
  }
}

HosekWilkieSun::HosekWilkieSun(double elevation, double turbidity) {
  const Tables& t = hosek_wilkie_tables();
  const double e = std::clamp(elevation, 0.0, kHalfPi);
  // Piece k covers elevations from (k / 45)^3 pi/2: like the sky's Bezier, crowded toward
  // the horizon.
  const int segment = std::min(static_cast<int>(Tables::kSolarSegments * std::cbrt(e / kHalfPi)),
                               Tables::kSolarSegments - 1);
  const double start =
      std::pow(static_cast<double>(segment) / Tables::kSolarSegments, 3.0) * kHalfPi;
  const double s = e - start;
  const TurbidityPair tp = turbidity_pair(turbidity);
  centre_.resize(Tables::kWavelengths);
  for (int w = 0; w < Tables::kWavelengths; ++w) {
    const auto cubic = [&](int turb) {
      const double* k = t.solar_segment(w, turb, segment);
      return ((k[0] * s + k[1]) * s + k[2]) * s + k[3];
    };
    centre_[static_cast<std::size_t>(w)] =
        (1.0 - tp.weight) * cubic(tp.lower) + tp.weight * cubic(tp.upper);
  }
}

double HosekWilkieSun::centre_radiance(int w) const { return centre_[static_cast<std::size_t>(w)]; }

double HosekWilkieSun::limb_darkening(int w, double mu) const {
  const double* k = &hosek_wilkie_tables().limb_darkening[static_cast<std::size_t>(w * 6)];
  double sum = 0.0, power = 1.0;
  for (int i = 0; i < 6; ++i, power *= mu) sum += k[i] * power;
  return sum;
}

double HosekWilkieSun::spectral_radiance(double wavelength, double mu) const {
  const double position =
      std::clamp((wavelength - Tables::kFirstWavelength) / Tables::kWavelengthStep, 0.0,
                 static_cast<double>(Tables::kWavelengths - 1));
  const int w = std::min(static_cast<int>(position), Tables::kWavelengths - 2);
  const double f = position - w;
  const double m = std::clamp(mu, 0.0, 1.0);
  return (1.0 - f) * centre_radiance(w) * limb_darkening(w, m) +
         f * centre_radiance(w + 1) * limb_darkening(w + 1, m);
}

Vec3 HosekWilkieSun::radiance(double mu) const {
  // 1 nm steps over the colour-matching functions' range: the tables hold 320-720 nm and
  // are held constant beyond, where the functions are nearly zero. The functions are
  // evaluated once for all calls (a disc profile asks for dozens of mu).
  static const std::vector<Vec3> kBars = [] {
    std::vector<Vec3> bars;
    for (int l = 360; l <= 830; ++l) bars.push_back(cie1931_xyz_bar(l));
    return bars;
  }();
  Vec3 xyz{};
  for (std::size_t i = 0; i < kBars.size(); ++i)
    xyz += kBars[i] * spectral_radiance(360.0 + static_cast<double>(i), mu);
  return xyz_to_rec709(xyz * kLumensPerWatt);
}

Vec3 HosekWilkieSun::irradiance(double angular_radius) const {
  // A point at angle rho from the centre has mu = sqrt(1 - (sin rho / sin R)^2); the disc's
  // integral of L cos is, to the sun's tiny radius, pi sin^2 R x 2 int_0^1 L(mu) mu dmu.
  constexpr int kSteps = 32;
  Vec3 sum{};
  for (int i = 0; i < kSteps; ++i) {
    const double mu = (i + 0.5) / kSteps;
    sum += radiance(mu) * (mu * (1.0 / kSteps));
  }
  const double sin_r = std::sin(angular_radius);
  return sum * (2.0 * std::numbers::pi * sin_r * sin_r);
}

}  // namespace landsim::renderer
