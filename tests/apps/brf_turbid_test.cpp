// The single-scattering limit of a canopy through `landsim brf`: a periodic cell filled with
// small discs of uniform leaf angles (G = 1/2) over a black soil, bi-Lambertian leaves of
// small reflectance and transmittance. Its once-scattered BRF has a closed form for a turbid
// medium (Ross 1981; Shultis and Myneni 1988):
//   BRF1 = Gamma(beta) / (mu_s mu_v) x (1 - exp(-L K)) / K,  K = G (1/mu_s + 1/mu_v),
//   Gamma(beta) = (r + t) / (3 pi) (sin beta - beta cos beta) + t / 3 cos beta,
// beta the angle between the sun's beam (travelling) and the view direction, L the leaf area
// index. Away from the hot spot (where finite discs correlate the ways in and out), the
// measure with single scattering alone (max_bounces = 0) must give it; with every order the
// BRF may only be higher, and by little, the leaves scattering 8% of what they meet. At the hot
// spot itself the discs' shadows hide what they light: the measure exceeds the closed form.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <numbers>
#include <string>
#include <vector>

#include "core/vec3.h"
#include "tests/support/run_program.h"
#include "tests/support/temp_dir.h"

namespace landsim {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kR = 0.05, kT = 0.03;        // leaf reflectance, transmittance
constexpr double kSide = 20.0, kDepth = 4.0;  // the cell, metres; the layer from 0 up
constexpr int kDiscs = 40000;
constexpr double kDiscRadius = 0.05;
constexpr double kSunZenith = 30.0;

double leaf_area_index() { return kDiscs * kPi * kDiscRadius * kDiscRadius / (kSide * kSide); }

struct View {
  double zenith, azimuth;  // towards the sensor; the sun stands at azimuth 90
};

Vec3 towards(double zenith_deg, double azimuth_deg) {
  const double z = zenith_deg * kPi / 180.0, a = azimuth_deg * kPi / 180.0;
  return {std::sin(z) * std::sin(a), std::sin(z) * std::cos(a), std::cos(z)};
}

double single_scattering_brf(const View& v) {
  const Vec3 sun = towards(kSunZenith, 90.0), view = towards(v.zenith, v.azimuth);
  const double beta = std::acos(std::clamp(-dot(sun, view), -1.0, 1.0));
  const double gamma = (kR + kT) / (3.0 * kPi) * (std::sin(beta) - beta * std::cos(beta)) +
                       kT / 3.0 * std::cos(beta);
  const double mu_s = sun.z, mu_v = view.z, k = 0.5 * (1.0 / mu_s + 1.0 / mu_v);
  return gamma / (mu_s * mu_v) * (1.0 - std::exp(-leaf_area_index() * k)) / k;
}

std::string scenario(const testing::TempDir& dir, int max_bounces) {
  // A flat ground whose samples run from one side of the cell to the other.
  dir.write("cell.asc",
            "ncols 3\nnrows 3\nxllcorner -15\nyllcorner -15\ncellsize 10\nNODATA_value -9999\n"
            "0 0 0\n0 0 0\n0 0 0\n");
  return dir
      .write("turbid_" + std::to_string(max_bounces) + ".toml",
             "[terrain]\nelevation = \"cell.asc\"\nperiodic = true\nalbedo = [0, 0, 0]\n"
             "[ground]\nsoil_spectrum = \"flat\"\n"
             "[sun]\nelevation = 60\nazimuth = 90\n[sky]\nmodel = \"none\"\n"
             "[render]\nmax_bounces = " +
                 std::to_string(max_bounces) +
                 "\n[[canopy]]\nname = \"turbid\"\nshape = \"box\"\nsize = [20, 20, 4]\n"
                 "discs = 40000\ndisc_radius = 0.05\nleaf_angles = \"uniform\"\n"
                 "positions = [[0, 0, 0]]\nreflectance = 0.05\ntransmittance = 0.03\n"
                 "[[views]]\nname = \"v\"\nposition = [0, -40, 30]\ntarget = [0, 0, 0]\n")
      .string();
}

nlohmann::json measure(const testing::TempDir& dir, int max_bounces,
                       const std::vector<View>& views) {
  std::string args = "brf " + scenario(dir, max_bounces) + " --json --spp 60000 --budget-paths 0";
  for (const View& v : views)
    args += " --direction " + std::to_string(v.zenith) + "," + std::to_string(v.azimuth);
  const testing::ProgramResult r = testing::run_landsim(args, dir);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return r.exit_code == 0 ? nlohmann::json::parse(r.out) : nlohmann::json{};
}

TEST(BrfTurbid, SingleScatteringMatchesTheTurbidMediumClosedForm) {
  // Forward, across and back (30 degrees or more from the hot spot at zenith 30, azimuth 90).
  const std::vector<View> views = {{0, 0},    {30, 270}, {60, 270}, {45, 0},
                                   {70, 180}, {65, 90},  {30, 90}};
  const std::size_t hot_spot = views.size() - 1;
  testing::TempDir dir;
  const nlohmann::json once = measure(dir, 0, views);
  const nlohmann::json every = measure(dir, -1, views);
  ASSERT_EQ(once["directions"].size(), views.size());
  ASSERT_EQ(every["directions"].size(), views.size());
  EXPECT_GT(once["directions"][hot_spot]["brf"].get<double>(),
            1.1 * single_scattering_brf(views[hot_spot]));
  for (std::size_t i = 0; i < hot_spot; ++i) {
    const double want = single_scattering_brf(views[i]);
    const auto& d = once["directions"][i];
    const double got = d["brf"].get<double>(), se = d["brf_se"].get<double>();
    EXPECT_NEAR(got, want, 3.0 * se + 0.005 * want)
        << "view " << views[i].zenith << "," << views[i].azimuth << ": " << got << " +- " << se;
    const double all = every["directions"][i]["brf"].get<double>();
    EXPECT_GT(all, got - 3.0 * se) << "every order below single scattering";
    EXPECT_LT(all, got * 1.1 + 3.0 * se) << "every order far above single scattering";
  }
}

}  // namespace
}  // namespace landsim
