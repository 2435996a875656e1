// The day-to-day forest benchmark (bench/scenarios/kagwene_100k.toml: 100,000 trees of 22
// variants over the Kagwene DEM, haze) pinned at low resolution, so that a change of its
// image is a decision, not an accident (issue 18: optimisations keep the images).
//
// This is a change detector, not a correctness oracle: the digest below is what the renderer
// produced when it was last changed on purpose. It is 9 x 16 block means of luminance rather
// than a hash of the bits so that it survives what may legitimately differ between machines
// (Embree picks its kernels by CPU, libm its by FMA support: a few pixels may differ in their
// last bits) while any change of geometry, light or random streams moves the blocks by
// percents. After a deliberate change, run the test, check the new image, and paste the
// digest it prints.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <string>

#include "renderer/render.h"
#include "scenes/scenario.h"
#include "scenes/scene_builder.h"
#include "tests/support/temp_dir.h"

namespace landsim::scenes {
namespace {

constexpr int kCols = 16, kRows = 9, kBlock = 6;  // 96 x 54 pixels

// Luminance means of kRows x kCols blocks of kBlock x kBlock pixels, row by row.
constexpr std::array<double, kCols* kRows> kPinned = {
    0.220946,  0.222844,  0.225796,  0.229853,  0.235449,  0.242709,  0.252088,  0.263635,
    0.277338,  0.29374,   0.312132,  0.332585,  0.354294,  0.377193,  0.39989,   0.422207,
    0.225723,  0.228067,  0.231307,  0.235602,  0.241233,  0.248431,  0.257565,  0.268805,
    0.282063,  0.297452,  0.314793,  0.333841,  0.353558,  0.374059,  0.394382,  0.414196,
    0.225699,  0.227857,  0.230901,  0.234899,  0.240107,  0.246803,  0.255176,  0.265507,
    0.277596,  0.291568,  0.307255,  0.324007,  0.342069,  0.360193,  0.378041,  0.395702,
    0.226841,  0.228855,  0.231296,  0.235125,  0.240049,  0.246231,  0.211718,  0.180236,
    0.183952,  0.223137,  0.286262,  0.320089,  0.318308,  0.301429,  0.29888,   0.351749,
    0.224539,  0.226517,  0.207429,  0.188052,  0.143138,  0.0914137, 0.0642314, 0.0535418,
    0.0621367, 0.0708078, 0.095033,  0.117333,  0.123011,  0.118078,  0.139403,  0.143851,
    0.114211,  0.105841,  0.0874118, 0.0687574, 0.0617671, 0.0661359, 0.0823981, 0.073362,
    0.0533108, 0.0586738, 0.0703175, 0.113275,  0.131205,  0.112788,  0.11378,   0.107128,
    0.0889928, 0.107081,  0.124454,  0.101821,  0.0821797, 0.0727399, 0.101231,  0.10514,
    0.101252,  0.0592976, 0.0623275, 0.100778,  0.119621,  0.132638,  0.12912,   0.108928,
    0.0614178, 0.0821795, 0.100978,  0.11893,   0.113516,  0.11141,   0.118266,  0.129246,
    0.124456,  0.120172,  0.0863689, 0.0834083, 0.0850383, 0.12458,   0.14286,   0.144925,
    0.0426642, 0.0528698, 0.0782578, 0.0822701, 0.0925026, 0.0860779, 0.0875599, 0.11095,
    0.141901,  0.146825,  0.137004,  0.123005,  0.0877177, 0.0914273, 0.0961203, 0.137652};

std::array<double, kCols * kRows> digest(const renderer::Film& film) {
  std::array<double, kCols * kRows> blocks{};
  for (int y = 0; y < film.height(); ++y)
    for (int x = 0; x < film.width(); ++x)
      blocks[static_cast<std::size_t>((y / kBlock) * kCols + x / kBlock)] +=
          film.luminance(x, y) / (kBlock * kBlock);
  return blocks;
}

std::string printed(const std::array<double, kCols * kRows>& blocks) {
  std::string s;
  char number[32];
  for (std::size_t i = 0; i < blocks.size(); ++i) {
    std::snprintf(number, sizeof number, "%.6g,%s", blocks[i], (i + 1) % kCols ? " " : "\n");
    s += number;
  }
  return s;
}

TEST(ForestPin, HundredThousandTreesImageIsUnchanged) {
  Scenario s = load_scenario(testing::source_file("bench/scenarios/kagwene_100k.toml"));
  s.views[0].width = kCols * kBlock;
  s.views[0].height = kRows * kBlock;
  s.render.spp = 4;
  const renderer::Scene scene = build_scene(s);
  const renderer::Film film = renderer::Renderer(scene).render(scene.views[0], {});
  const auto blocks = digest(film);
  // A change of sampling moves most forest blocks (144 samples each) by several percent, of
  // geometry or light most blocks; a machine whose kernels differ in a last bit may send a
  // ray or two another way: a few blocks may move by more than 0.5%, not more.
  int moved = 0;
  for (std::size_t i = 0; i < blocks.size(); ++i)
    moved += std::abs(blocks[i] - kPinned[i]) > 5e-3 * std::max(kPinned[i], 1e-3);
  EXPECT_LE(moved, 4) << moved << " of " << blocks.size()
                      << " blocks moved; if the change is meant, the new digest is:\n"
                      << printed(blocks);
}

}  // namespace
}  // namespace landsim::scenes
