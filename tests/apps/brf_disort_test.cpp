// The shipped DISORT scenarios (scenes/disort/) through `landsim brf`, as a user runs them: a
// homogeneous [haze.layer] over a flat periodic ground under the collimated sun alone. The
// top's BRF in DISORT's directions is pi I / (mu0 FBEAM) of DISORT's diffuse intensity; the
// energy budget's albedo, soil_direct and soil_diffuse are DISORT's upward flux at the top and
// direct and diffuse downward fluxes at the ground over mu0 FBEAM; and the budget closes.
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

void expect_agrees(const nlohmann::json& got, double want, const std::string& what) {
  const double mean = got.contains("mean") ? got["mean"].get<double>() : got["brf"].get<double>();
  const double se = got.contains("se") ? got["se"].get<double>() : got["brf_se"].get<double>();
  EXPECT_NEAR(mean, want, 3.0 * se + 0.01 * std::abs(want) + 1e-5)
      << what << ": " << mean << " +- " << se;
}

// The cases lit by the beam alone are shipped (1c, 1f and 11a add isotropic light from above,
// which [sky] does not give).
bool shipped(const DisortCase& c) { return c.fisot == 0.0; }

}  // namespace
}  // namespace landsim

namespace landsim::testing {
// A case by its name in failures (not its bytes).
void PrintTo(const DisortCase& c, std::ostream* os) { *os << "DISORT case " << c.name; }
}  // namespace landsim::testing

namespace landsim {
namespace {

class BrfDisort : public ::testing::TestWithParam<DisortCase> {};

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
  const double incident = c.mu0 * c.fbeam;
  for (std::size_t k = 0; k < c.top.size(); ++k)
    expect_agrees(j["directions"][k], std::numbers::pi * c.top[k].value / incident,
                  std::string(c.name) + " BRF at mu " + std::to_string(c.top[k].mu));
  const nlohmann::json& b = j["budget"];
  expect_agrees(b["albedo"], c.up_at_top / incident, std::string(c.name) + " albedo");
  expect_agrees(b["soil_direct"], c.beam_at_ground / incident, std::string(c.name) + " direct");
  expect_agrees(b["soil_diffuse"], c.down_at_ground / incident, std::string(c.name) + " diffuse");
  EXPECT_NEAR(b["total"]["mean"].get<double>(), 1.0, 3.0 * b["total"]["se"].get<double>() + 1e-6)
      << c.name;
  EXPECT_LT(b["total"]["se"].get<double>(), 0.003) << c.name;
}

std::vector<DisortCase> shipped_cases() {
  std::vector<DisortCase> out;
  for (const DisortCase& c : testing::cases())
    if (shipped(c)) out.push_back(c);
  return out;
}

INSTANTIATE_TEST_SUITE_P(Cases, BrfDisort, ::testing::ValuesIn(shipped_cases()),
                         [](const ::testing::TestParamInfo<DisortCase>& i) {
                           return std::string("case_") + i.param.name;
                         });

// Every scenario in scenes/disort/ is one of the cases checked above.
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
