// The haze table's quadrature along a ray into the sky (renderer/transport/scattering_table.h):
// toward the horizon a ray's optical depth a runs to hundreds and its light comes from the
// first thousandth of the way; the quadrature must integrate exp(-a (1 - x)) f(x) there as its
// closed forms do. Midpoints evenly spaced in x (the rule before issue 70) returned 0.086 of
// the constant's integral at a = 300.
#include "renderer/transport/scattering_table.h"

#include <gtest/gtest.h>

#include <cmath>

namespace landsim::renderer {
namespace {

TEST(ScatteringTable, TheHorizonQuadratureMatchesItsClosedFormsAtAnyDepth) {
  // 15 km visibility over a 1200 m scale height: a = 0.313 / mu; mu 1e-3 and 1e-2, and overhead.
  for (const double a : {313.0, 31.3, 0.313, 0.0}) {
    const double constant = a > 0.0 ? -std::expm1(-a) / a : 1.0;
    EXPECT_NEAR(exponential_mass_quadrature(a, 32, [](double) { return 1.0; }) / constant, 1.0,
                0.005)
        << a;
    // f = x: the integral is 1 / a - (1 - e^-a) / a^2 (1/2 when a = 0).
    const double linear = a > 0.0 ? 1.0 / a + std::expm1(-a) / (a * a) : 0.5;
    EXPECT_NEAR(exponential_mass_quadrature(a, 32, [](double x) { return x; }) / linear, 1.0, 0.005)
        << a;
  }
}

}  // namespace
}  // namespace landsim::renderer
