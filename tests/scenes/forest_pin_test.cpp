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
    9598.96, 9597.68, 9668.06, 9818.43, 8312.71, 7041.3,  7064.18, 8764.9,  11399.6, 12872.4,
    12865.2, 12128.4, 12056.6, 14420.9, 9650.05, 9544.69, 8486.03, 7508.6,  5459.36, 3396.21,
    2139.9,  1893.49, 2060.68, 2428.29, 3291.79, 4086.42, 4086.02, 4044.43, 4817.24, 5001.67,
    3983.38, 3525.21, 2840.26, 2259.09, 2022.26, 2160.62, 2659.61, 2335.44, 1819.75, 1991.15,
    2401.25, 3807.3,  4395.07, 3957.04, 3970.66, 3822.93, 2667.27, 3283.96, 3818.44, 3162.77,
    2528.44, 2298.6,  3148.21, 3223.53, 3264.59, 2044.68, 2149.94, 3245.07, 3808.86, 4363.55,
    4389.32, 3905.58, 1837.35, 2504.97, 3008.78, 3527.45, 3432.18, 3189.27, 3419.91, 3867.63,
    3832.94, 3633.2,  2851.59, 2683.82, 2729.68, 4020.4,  4680.52, 4918.76, 1195.37, 1497.69,
    2337.54, 2277.56, 2488.86, 2403.02, 2495.44, 3129.66, 4217.78, 4279.03, 4088.85, 3811.99,
    2801.01, 3013.33, 3190.46, 4520.72};

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
