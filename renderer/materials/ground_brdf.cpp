#include "renderer/materials/ground_brdf.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace landsim::renderer {
namespace {

constexpr float kPi = std::numbers::pi_v<float>;
// The zenith cosines the models are evaluated at, at least: both are singular at grazing
// (the kernels' secants), and a shading normal can put a direction just below its horizon.
constexpr float kMinCos = 1e-3f;
// RPV's Minnaert term takes no zenith beyond 85 degrees (docs/GROUND.md "Reflectance models"):
// below k = 1 it grows without bound toward the horizon, and with it the light a surface lit
// there would reflect (for every k < 1 more than it receives, near enough to grazing); the
// model is fitted to measurements well inside that (RAMI's views reach 75 degrees).
constexpr float kMinnaertMinCos = 0.0871557f;  // cos 85 degrees
// The hemisphere's quadrature: midpoints in the cosine of the view zenith and in the azimuth
// over the half the incidence plane mirrors.
constexpr int kRings = 256;
constexpr int kSectors = 128;

// The two directions' geometry, all from their cosines: tan^2 of each zenith, and
// tan_i tan_o cos(phi) with phi the azimuth between them (0 at the hot spot).
struct PairGeometry {
  float ci, co, cp;
  float tan2_i, tan2_o, tan_cos;
};

PairGeometry pair_geometry(float cos_i, float cos_o, float cos_phase) {
  PairGeometry g;
  g.ci = std::clamp(cos_i, kMinCos, 1.0f);
  g.co = std::clamp(cos_o, kMinCos, 1.0f);
  g.cp = std::clamp(cos_phase, -1.0f, 1.0f);
  g.tan2_i = (1.0f - g.ci * g.ci) / (g.ci * g.ci);
  g.tan2_o = (1.0f - g.co * g.co) / (g.co * g.co);
  // sin_i sin_o cos(phi) = cos_phase - cos_i cos_o.
  g.tan_cos = (g.cp - g.ci * g.co) / (g.ci * g.co);
  return g;
}

// Rahman, Pinty and Verstraete 1993: M = (cos_i cos_o (cos_i + cos_o))^(k-1), the
// Henyey-Greenstein F with the phase angle's cosine (Theta < 0 scatters back), and the
// hot-spot term's 1 / (1 + G), G the distance between the two directions' tangents.
BrdfShape rpv(const GroundBrdf& m, const PairGeometry& g) {
  const float ci = std::max(g.ci, kMinnaertMinCos), co = std::max(g.co, kMinnaertMinCos);
  const float minnaert = std::pow(ci * co * (ci + co), m.k - 1.0f);
  const float t = m.asymmetry;
  const float hg = (1.0f - t * t) / std::pow(1.0f + t * t + 2.0f * t * g.cp, 1.5f);
  const float big_g = std::sqrt(std::max(0.0f, g.tan2_i + g.tan2_o - 2.0f * g.tan_cos));
  return {minnaert * hg, 1.0f / (1.0f + big_g)};
}

// RossThick: a dense turbid canopy's single scattering over a Lambertian background.
float ross_thick(const PairGeometry& g) {
  const float xi = std::acos(g.cp);
  const float sin_xi = std::sqrt(std::max(0.0f, 1.0f - g.cp * g.cp));
  return ((0.5f * kPi - xi) * g.cp + sin_xi) / (g.ci + g.co) - 0.25f * kPi;
}

// LiSparse-R (reciprocal; crowns as spheroids of h/b = 2, b/r = 1, MODIS's choice): the
// sunlit and viewed ground and crowns' overlap O, mutual shadowing of sparse crowns.
float li_sparse(const PairGeometry& g) {
  const float sec_i = 1.0f / g.ci, sec_o = 1.0f / g.co, sec_sum = sec_i + sec_o;
  const float d2 = std::max(0.0f, g.tan2_i + g.tan2_o - 2.0f * g.tan_cos);
  const float cross2 = std::max(0.0f, g.tan2_i * g.tan2_o - g.tan_cos * g.tan_cos);
  constexpr float kHeightOverB = 2.0f;
  const float cos_t = std::clamp(kHeightOverB * std::sqrt(d2 + cross2) / sec_sum, -1.0f, 1.0f);
  const float t = std::acos(cos_t);
  const float overlap = (t - std::sqrt(1.0f - cos_t * cos_t) * cos_t) * sec_sum / kPi;
  return overlap - sec_sum + 0.5f * (1.0f + g.cp) * sec_i * sec_o;
}

}  // namespace

BrdfShape brdf_shape(const GroundBrdf& brdf, float cos_i, float cos_o, float cos_phase) {
  switch (brdf.model) {
    case GroundBrdf::Model::lambert:
      return {};
    case GroundBrdf::Model::rpv:
      return rpv(brdf, pair_geometry(cos_i, cos_o, cos_phase));
    case GroundBrdf::Model::ross_li: {
      const PairGeometry g = pair_geometry(cos_i, cos_o, cos_phase);
      return {1.0f + brdf.volumetric * ross_thick(g) + brdf.geometric * li_sparse(g), 0.0f};
    }
  }
  return {};
}

double directional_reflectance(const GroundBrdf& brdf, double rho, double cos_i) {
  // f cos dw = rho x factor / pi x mu dmu dphi (mu the view zenith's cosine): the reflectance
  // is 2 rho times the mean of factor x mu over mu in [0, 1] and phi in [0, 2 pi). In mu the
  // kernels' secants (1 / mu) and RPV's bowl (mu^(k-1)) are tamed by the weight mu.
  const double sin_i = std::sqrt(std::max(0.0, 1.0 - cos_i * cos_i));
  double sum = 0.0;
  for (int i = 0; i < kRings; ++i) {
    const double mu = (i + 0.5) / kRings;
    const double sin_o = std::sqrt(1.0 - mu * mu);
    for (int j = 0; j < kSectors; ++j) {
      const double phi = std::numbers::pi * (j + 0.5) / kSectors;
      const double cos_phase = cos_i * mu + sin_i * sin_o * std::cos(phi);
      const BrdfShape s = brdf_shape(brdf, static_cast<float>(cos_i), static_cast<float>(mu),
                                     static_cast<float>(cos_phase));
      sum += brdf_factor(brdf, s, static_cast<float>(rho)) * mu;
    }
  }
  return 2.0 * rho * sum / (static_cast<double>(kRings) * kSectors);
}

namespace {

// Incidences of the white-sky average: midpoints in the cosine, weight 2 mu dmu.
constexpr int kIncidences = 48;

}  // namespace

double white_sky_albedo(const GroundBrdf& brdf, double rho) {
  double sum = 0.0;
  for (int i = 0; i < kIncidences; ++i) {
    const double mu = (i + 0.5) / kIncidences;
    sum += 2.0 * mu * directional_reflectance(brdf, rho, mu) / kIncidences;
  }
  return sum;
}

// The white-sky means of the factor's two parts, a (clamped at zero) and a x b, taken from
// the unscaled model at rho = 1 with rho_c = 1 (the b part vanishes) and rho_c = 0.
void normalise_to_white_sky(GroundBrdf& brdf) {
  if (brdf.lambertian()) return;
  GroundBrdf raw = brdf;
  raw.white_a = 1.0f;
  raw.white_ab = 0.0f;
  raw.hot_spot = 1.0f;  // factor = a
  GroundBrdf ab = raw;
  ab.hot_spot = 0.0f;  // factor = a (1 + b)
  const double mean_a = white_sky_albedo(raw, 1.0);
  brdf.white_a = static_cast<float>(mean_a);
  brdf.white_ab = static_cast<float>(white_sky_albedo(ab, 1.0) - mean_a);
}

PeakReflectance peak_reflectance(const GroundBrdf& brdf, double rho) {
  PeakReflectance peak;
  constexpr int kStepDeg = 2;
  for (int z = 0; z < 90; z += kStepDeg) {
    const double r = directional_reflectance(brdf, rho, std::cos(z * std::numbers::pi / 180.0));
    if (r > peak.reflectance) peak = {r, static_cast<double>(z)};
  }
  return peak;
}

}  // namespace landsim::renderer
