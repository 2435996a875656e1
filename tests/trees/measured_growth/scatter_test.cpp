// Trees of one age differ as the Urban Tree Database says they do: the reading of its Sigma
// column checked against its own 27 Modesto trees, each seed's draw, the spread and mean of
// many trees, and growth that never shrinks.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "tests/trees/modesto_trees.h"
#include "trees/measured_growth/allometry.h"
#include "trees/measured_growth/generator.h"
#include "trees/measured_growth/parameters.h"
#include "trees/species.h"

namespace landsim::trees::measured_growth {
namespace {

Parameters london_plane() {
  return std::get<Parameters>(
      load_species(std::filesystem::path(LANDSIM_SOURCE_DIR) / "data/species/london_plane.toml")
          .parameters);
}

double rms(const std::vector<double>& v) {
  double s = 0.0;
  for (double x : v) s += x * x;
  return std::sqrt(s / static_cast<double>(v.size()));
}

// Sigma of a weighted polynomial fit is the weighted residuals' mean square: on the data it
// was fitted to, sqrt(Sigma) is their spread (within 25%), Sigma itself is not (off 4x-75x).
TEST(MeasuredGrowthScatter, SigmaIsTheWeightedMeanSquareOnTheDatabasesOwnTrees) {
  const Allometry a = london_plane().allometry;
  const std::vector<trees::testing::ModestoTree> trees = trees::testing::modesto_trees();
  ASSERT_EQ(trees.size(), 27u);
  std::vector<double> dbh, height, crown;
  for (const trees::testing::ModestoTree& t : trees) {
    if (t.age > 0) dbh.push_back((t.dbh_cm - a.dbh.unclamped(t.age)) / std::pow(t.age, 0.25));
    height.push_back((t.height_m - a.height.unclamped(t.dbh_cm)) / t.dbh_cm);
    crown.push_back((t.crown_diameter_m - a.crown_diameter.unclamped(t.dbh_cm)) / t.dbh_cm);
  }
  for (auto [spread, sigma] :
       {std::pair{rms(dbh), a.dbh.sigma}, std::pair{rms(height), a.height.sigma},
        std::pair{rms(crown), a.crown_diameter.sigma}}) {
    EXPECT_NEAR(spread / std::sqrt(sigma), 1.0, 0.25) << spread << " vs Sigma " << sigma;
    EXPECT_GT(std::abs(spread / sigma - 1.0), 0.5) << "Sigma read as a standard deviation fits";
  }
}

// 400 trees of 20 years: each seed its own tree; their DBH spreads as the database says at
// that age, and their means stay within 10% of the equations (DBH within 3%). Height, crown
// and leaf area follow each tree's own DBH through concave equations, so their means fall
// below the equations' (as the 27 measured trees' do: heights 3.8%, leaf areas 2.2%).
TEST(MeasuredGrowthScatter, ManyTreesSpreadAsMeasuredAroundTheEquations) {
  const Parameters p = london_plane();
  const Allometry& mean = p.allometry;
  constexpr int kTrees = 400;
  constexpr double kAge = 20.0;
  double sum_dbh = 0, sum_dbh2 = 0, sum_h = 0, sum_cd = 0, sum_la = 0;
  for (int seed = 1; seed <= kTrees; ++seed) {
    const Allometry a = individual(mean, static_cast<std::uint64_t>(seed), p.scatter);
    const double d = a.f_dbh(kAge);
    sum_dbh += d;
    sum_dbh2 += d * d;
    sum_h += a.f_height(kAge);
    sum_cd += a.f_crown_diameter(kAge);
    sum_la += a.f_leaf_area(kAge);
  }
  const double n = kTrees, dbh_mean = sum_dbh / n;
  const double dbh_sd = std::sqrt(sum_dbh2 / n - dbh_mean * dbh_mean);
  // The database: sqrt(16.9542 / (1 / sqrt(20))) = 8.71 cm (less a little for the truncation
  // at 2.5 standard deviations and the clamp to its range).
  EXPECT_NEAR(dbh_sd, std::sqrt(16.9542 * std::sqrt(kAge)), 0.12 * 8.71);
  EXPECT_NEAR(dbh_mean, mean.f_dbh(kAge), 0.03 * mean.f_dbh(kAge));
  EXPECT_NEAR(sum_h / n, mean.f_height(kAge), 0.10 * mean.f_height(kAge));
  EXPECT_NEAR(sum_cd / n, mean.f_crown_diameter(kAge), 0.10 * mean.f_crown_diameter(kAge));
  EXPECT_NEAR(sum_la / n, mean.f_leaf_area(kAge), 0.15 * mean.f_leaf_area(kAge));
  std::printf(
      "20 years, %d trees: DBH %.1f +- %.1f cm (equation %.1f), height %.2f m (%.2f), "
      "crown diameter %.2f m (%.2f), leaf area %.0f m2 (%.0f)\n",
      kTrees, dbh_mean, dbh_sd, mean.f_dbh(kAge), sum_h / n, mean.f_height(kAge), sum_cd / n,
      mean.f_crown_diameter(kAge), sum_la / n, mean.f_leaf_area(kAge));
  // Scatter 0: every tree the mean.
  const Allometry none = individual(mean, 5, 0.0);
  EXPECT_EQ(none.f_height(kAge), mean.f_height(kAge));
}

// No tree shrinks: the running maximum keeps the small ones growing where the mean flattens.
TEST(MeasuredGrowthScatter, NoTreeShrinksWithAge) {
  const Parameters p = london_plane();
  for (std::uint64_t seed = 1; seed <= 60; ++seed) {
    const Allometry a = individual(p.allometry, seed, 2.5);  // far out in the tails too
    double last_dbh = 0.0, last_height = 0.0, last_crown = 0.0;
    for (double t = 0.0; t <= p.allometry.max_age; t += 0.25) {
      EXPECT_GE(a.f_dbh(t), last_dbh) << "seed " << seed << " at " << t;
      EXPECT_GE(a.f_height(t), last_height) << "seed " << seed << " at " << t;
      EXPECT_GE(a.f_crown_diameter(t), last_crown) << "seed " << seed << " at " << t;
      last_dbh = a.f_dbh(t);
      last_height = a.f_height(t);
      last_crown = a.f_crown_diameter(t);
    }
  }
}

// Two seeds, two trees of one age: their geometry differs in height as their draws do.
TEST(MeasuredGrowthScatter, VariantsOfOneAgeDifferInSize) {
  const Species s =
      load_species(std::filesystem::path(LANDSIM_SOURCE_DIR) / "data/species/london_plane.toml");
  const Parameters& p = std::get<Parameters>(s.parameters);
  double lo = 1e9, hi = 0.0;
  for (std::uint64_t seed : {1u, 2u, 3u, 4u, 5u, 6u}) {
    const double h = generate(s, {.seed = seed, .age = 20}).stats.height;
    const double own = individual(p.allometry, seed, p.scatter).f_height(20);
    EXPECT_NEAR(h, own, 0.1 * own) << seed;
    lo = std::min(lo, h);
    hi = std::max(hi, h);
  }
  EXPECT_GT(hi - lo, 1.0);  // metres: a street of 20-year planes is not uniform
}

}  // namespace
}  // namespace landsim::trees::measured_growth
