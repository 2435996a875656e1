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
    8078.76, 7910.59, 7808.13, 7752.38, 7758.06, 7837.46, 7997.98, 8243.47, 8575.21, 9015.33,
    9550.23, 10168.3, 10872.9, 11670.8, 12494.2, 13383.4, 9185.11, 9045.86, 8956.52, 8919.76,
    8935.06, 9034.16, 9228.5,  9535.38, 9926.45, 10427.5, 11033,   11731.9, 12483.3, 13334,
    14236.4, 15107.6, 9903.17, 9807.2,  9749.25, 9752.16, 9824.59, 9975.12, 10224.3, 10597.5,
    11067,   11635.6, 12298.6, 13039,   13854.9, 14714,   15602.7, 16510.1, 9762.91, 9668.75,
    9598.96, 9597.68, 9668.06, 9818.43, 8328.31, 7037.77, 7065.63, 8791.41, 11348.7, 12872.4,
    12868.1, 12137.3, 12053.4, 14428.7, 9650.05, 9544.69, 8476.57, 7511.46, 5475.66, 3334.62,
    2117.12, 1917.45, 2091.02, 2447.81, 3285.4,  4064.13, 4083.95, 4033.36, 4807.46, 4997.94,
    3964.81, 3501.9,  2845.31, 2276.74, 2043.81, 2136.54, 2673.24, 2332.47, 1834.16, 1979.04,
    2354.57, 3831.89, 4393.78, 3967.35, 3960.62, 3837.13, 2657.35, 3262.04, 3817.4,  3116.25,
    2528.51, 2334.42, 3147.64, 3214.32, 3262.73, 2075.69, 2180.61, 3221.42, 3820.73, 4354.66,
    4391.89, 3903.96, 1834.36, 2506.58, 3007.31, 3527.03, 3430.16, 3192.83, 3425.6,  3879.85,
    3844.92, 3633.86, 2826.48, 2690.9,  2707.2,  4016.68, 4683.84, 4915.48, 1210.05, 1516.62,
    2334.35, 2271.57, 2488.34, 2409.91, 2492.03, 3138.33, 4212.09, 4282.66, 4080.98, 3807.73,
    2803.7,  3026.65, 3184.4,  4502.39};

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
