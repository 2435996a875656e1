// The shipped DISORT scenarios (scenes/disort/) through `landsim brf`, as a user runs them: a
// homogeneous [haze.layer] over a flat periodic ground under the collimated sun, a uniform sky
// (DISORT's isotropic light from above), or both. The top's BRF in DISORT's directions is
// pi I / (mu0 FBEAM) of DISORT's diffuse intensity (with no beam: the radiance over the sky's
// is I / FISOT); the budgets' albedo, soil_direct and soil_diffuse, under the sun and under
// the sky weighed by their parts of the light coming in, are DISORT's upward flux at the top
// and direct and diffuse downward fluxes at the ground over that light; and the budgets close.
// Each within three standard errors plus 1% (and a floor for DISORT's zeros).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <numbers>
#include <set>
#include <string>

#include "tests/support/disort_cases.h"
#include "tests/support/run_program.h"
#include "tests/support/temp_dir.h"
#include "tests/support/tools.h"

namespace landsim {
namespace {

using testing::DisortCase;

std::filesystem::path scenario_of(const DisortCase& c) {
  return testing::source_file("scenes/disort/case_" + std::string(c.name) + ".toml");
}

// A measured value and its standard error.
struct Measured {
  double mean = 0.0, se = 0.0;
};

Measured share(const nlohmann::json& budget, const char* key) {
  return {budget[key]["mean"].get<double>(), budget[key]["se"].get<double>()};
}

// a x + b y of two independent estimates.
Measured combined(double a, const Measured& x, double b, const Measured& y) {
  return {a * x.mean + b * y.mean, std::hypot(a * x.se, b * y.se)};
}

void expect_agrees(const Measured& got, double want, const std::string& what) {
  EXPECT_NEAR(got.mean, want, 3.0 * got.se + 0.01 * std::abs(want) + 1e-5)
      << what << ": " << got.mean << " +- " << got.se;
}

// The light from above, as the scenarios give it: the sun's beam of FBEAM (1000 lux) and a
// uniform sky of radiance FISOT (1000 cd/m2 per unit FISOT when there is no beam).
constexpr double kSky = 1000.0;

}  // namespace
}  // namespace landsim

namespace landsim::testing {
// A case by its name in failures (not its bytes).
void PrintTo(const DisortCase& c, std::ostream* os) { *os << "DISORT case " << c.name; }
}  // namespace landsim::testing

namespace landsim {
namespace {

class BrfDisort : public ::testing::TestWithParam<DisortCase> {};

// The top's radiance in DISORT's directions: with a beam, its BRF is pi I / (mu0 FBEAM); with
// the sky alone, the radiance over the sky's is I / FISOT.
void expect_top(const DisortCase& c, const nlohmann::json& directions) {
  for (std::size_t k = 0; k < c.top.size(); ++k) {
    const std::string what = std::string(c.name) + " at mu " + std::to_string(c.top[k].mu);
    const nlohmann::json& d = directions[k];
    if (c.fbeam > 0.0)
      expect_agrees({d["brf"].get<double>(), d["brf_se"].get<double>()},
                    std::numbers::pi * c.top[k].value / (c.mu0 * c.fbeam), what + ": BRF");
    else
      expect_agrees({d["radiance"].get<double>() / kSky, d["radiance_se"].get<double>() / kSky},
                    c.top[k].value / c.fisot, what + ": radiance");
  }
}

// DISORT's fluxes over the light coming in (mu0 FBEAM from the beam, pi FISOT from the sky):
// the budgets' shares under each light, weighed by its part of it.
void expect_fluxes(const DisortCase& c, const nlohmann::json& j) {
  const double beam = c.mu0 * c.fbeam, sky = std::numbers::pi * c.fisot, in = beam + sky;
  const Measured none;
  const nlohmann::json& s = j.contains("budget") ? j["budget"] : j["budget_isotropic"];
  const nlohmann::json& i = j["budget_isotropic"];
  const auto from_sun = [&](const char* key) { return c.fbeam > 0.0 ? share(s, key) : none; };
  expect_agrees(combined(beam / in, from_sun("albedo"), sky / in, share(i, "albedo")),
                c.up_at_top / in, std::string(c.name) + " albedo");
  expect_agrees(combined(beam / in, from_sun("soil_direct"), 0.0, none), c.beam_at_ground / in,
                std::string(c.name) + " direct beam at the ground");
  const Measured sky_down = combined(1.0, share(i, "soil_direct"), 1.0, share(i, "soil_diffuse"));
  expect_agrees(combined(beam / in, from_sun("soil_diffuse"), sky / in, sky_down),
                c.down_at_ground / in, std::string(c.name) + " diffuse at the ground");
  for (const nlohmann::json* b : {&s, &i}) {
    EXPECT_NEAR((*b)["total"]["mean"].get<double>(), 1.0,
                3.0 * (*b)["total"]["se"].get<double>() + 1e-6)
        << c.name;
    EXPECT_LT((*b)["total"]["se"].get<double>(), 0.003) << c.name;
  }
}

TEST_P(BrfDisort, TheShippedScenarioGivesDisortsReflectanceAndFluxes) {
  const DisortCase& c = GetParam();
  ASSERT_TRUE(std::filesystem::exists(scenario_of(c))) << scenario_of(c);
  // The sun stands at azimuth 90 in the scenarios: DISORT's azimuth 0 (away from it) is 270.
  std::string args = "brf " + scenario_of(c).string() + " --json --spp 8192 --budget-paths 10000";
  for (const testing::Intensity& i : c.top)
    args += " --direction " + std::to_string(std::acos(i.mu) * 180.0 / std::numbers::pi) + "," +
            std::to_string(270.0 - i.phi_deg);
  testing::TempDir dir;
  const testing::ProgramResult r = testing::run_landsim(args, dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j.contains("budget"), c.fbeam > 0.0) << "a dark sun has no budget of its own";
  expect_top(c, j["directions"]);
  expect_fluxes(c, j);
}

const std::vector<DisortCase>& shipped_cases() { return testing::cases(); }

INSTANTIATE_TEST_SUITE_P(Cases, BrfDisort, ::testing::ValuesIn(shipped_cases()),
                         [](const ::testing::TestParamInfo<DisortCase>& i) {
                           return std::string("case_") + i.param.name;
                         });

// Every scenario in scenes/disort/ is one of the cases checked above, and every case ships.
TEST(BrfDisortFiles, EveryShippedScenarioIsChecked) {
  std::set<std::string> checked;
  for (const DisortCase& c : shipped_cases()) checked.insert(scenario_of(c).filename().string());
  int files = 0;
  for (const auto& e : std::filesystem::directory_iterator(testing::source_file("scenes/disort"))) {
    ++files;
    EXPECT_TRUE(checked.count(e.path().filename().string())) << e.path();
  }
  EXPECT_EQ(files, static_cast<int>(checked.size()));
}

}  // namespace
}  // namespace landsim
