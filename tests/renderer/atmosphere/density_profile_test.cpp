// A tabulated density profile (renderer/atmosphere/density_profile): exact where the table is
// an exponential, against direct quadrature where it is not (a layer of ozone rising to its
// peak and falling), and its inverses undo what they invert.
#include "renderer/atmosphere/density_profile.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace landsim::renderer {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Nodes every 1 km of n0 exp(-z / h): the piecewise exponential is that exponential exactly.
DensityProfile exponential_table(double n0, double h) {
  std::vector<double> z, n;
  for (int i = 0; i <= 20; ++i) {
    z.push_back(1000.0 * i);
    n.push_back(n0 * std::exp(-1000.0 * i / h));
  }
  return DensityProfile(z, n);
}

// Simpson's rule of the profile's density between two heights (the test's own integral).
double simpson(const DensityProfile& p, double a, double b, int steps = 20000) {
  const double h = (b - a) / steps;
  double sum = p.density(a) + p.density(b);
  for (int i = 1; i < steps; ++i) sum += p.density(a + i * h) * (i % 2 == 1 ? 4.0 : 2.0);
  return sum * h / 3.0;
}

TEST(DensityProfile, AnExponentialTableIsTheExponential) {
  const double n0 = 2.5, h = 8000.0;
  const DensityProfile p = exponential_table(n0, h);
  for (const double z : {-300.0, 0.0, 450.0, 2000.0, 12345.0, 25000.0}) {
    EXPECT_NEAR(p.density(z) / (n0 * std::exp(-z / h)), 1.0, 1e-12) << z;
    EXPECT_NEAR(p.column_above(z) / (n0 * h * std::exp(-z / h)), 1.0, 1e-12) << z;
  }
  // A ray rising at 30 degrees from 500 m for 4 km crosses 2 km of height.
  const double dz = 0.5, along = p.along(500.0, dz, 4000.0);
  const double want = n0 * h * (std::exp(-500.0 / h) - std::exp(-2500.0 / h)) / dz;
  EXPECT_NEAR(along / want, 1.0, 1e-12);
  EXPECT_NEAR(p.along(500.0, dz, kInf) / (n0 * h * std::exp(-500.0 / h) / dz), 1.0, 1e-12);
  EXPECT_EQ(p.along(500.0, -dz, kInf), kInf);  // down for ever
  EXPECT_NEAR(p.along(500.0, 0.0, 300.0) / (n0 * std::exp(-500.0 / h) * 300.0), 1.0, 1e-12);
}

TEST(DensityProfile, ARisingAndFallingLayerIntegratesAsQuadratureDoes) {
  // Ozone-like: density rising to a peak at 22 km and falling away.
  std::vector<double> z, n;
  for (int i = 0; i <= 60; ++i) {
    z.push_back(500.0 + 1000.0 * i);
    const double x = (z.back() - 22000.0) / 6000.0;
    n.push_back(1e-3 + std::exp(-x * x));
  }
  // Evenly spaced (pieces found by division) and unevenly (by search).
  std::vector<double> uneven = z;
  for (std::size_t i = 1; i + 1 < uneven.size(); i += 2) uneven[i] += 300.0;
  for (const DensityProfile& p : {DensityProfile(z, n), DensityProfile(uneven, n)})
    for (const auto& [a, b] : {std::pair{0.0, 5000.0}, {10000.0, 30000.0}, {21500.0, 22700.0}})
      EXPECT_NEAR(p.column_above(a) - p.column_above(b), simpson(p, a, b), 1e-7 * p.column_above(a))
          << a << " to " << b;
}

TEST(DensityProfile, LengthAtInvertsAlongRisingFallingAndLevel) {
  const DensityProfile p = exponential_table(1.0, 7000.0);
  for (const double dz : {0.8, 0.05, -0.3, -1.0, 0.0}) {
    for (const double depth : {1.0, 500.0, 3000.0}) {
      const double s = p.length_at(1200.0, dz, 1e7, depth);
      if (s >= 1e7) {  // a rising ray the depth is never reached on
        EXPECT_GT(dz, 0.0);
        EXPECT_LT(p.along(1200.0, dz, kInf), depth);
        continue;
      }
      EXPECT_NEAR(p.along(1200.0, dz, s), depth, 1e-9 * depth) << dz << " " << depth;
    }
  }
  // Not reached within t: t.
  EXPECT_EQ(p.length_at(1200.0, -0.3, 10.0, 3000.0), 10.0);
  for (const double c : {1.0, 100.0, 5000.0, 6999.0, 9000.0})
    EXPECT_NEAR(p.column_above(p.height_of_column(c)), c, 1e-9 * c) << c;
}

TEST(DensityProfile, RefusesTablesItCannotIntegrate) {
  EXPECT_THROW(DensityProfile({0.0}, {1.0}), std::logic_error);
  EXPECT_THROW(DensityProfile({0.0, 0.0}, {1.0, 1.0}), std::logic_error);
  EXPECT_THROW(DensityProfile({0.0, 1.0}, {1.0, 0.0}), std::logic_error);
}

}  // namespace
}  // namespace landsim::renderer
