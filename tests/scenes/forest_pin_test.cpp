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

#include "renderer/transport/render.h"
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
    11067,   11635.6, 12298.6, 13039,   13854.9, 14714,   15602.7, 16510.1, 8856.49, 8733.77,
    8644.57, 8589.91, 8658.38, 8640.96, 7771.07, 6904.01, 6958.21, 8482.24, 10287.8, 11366.5,
    11630.5, 11507.8, 11670.1, 13510.8, 5498.42, 5379.03, 4901.34, 4549.98, 3676.5,  2710.24,
    2086.01, 1850.16, 2064.8,  2411.69, 3227.82, 3813.22, 4039.65, 4009.96, 4806.09, 5013.89,
    3103.6,  3032.67, 2822.14, 2206.36, 2164.51, 2093.24, 2655.74, 2401.52, 1767,    1987.92,
    2417.59, 3839.5,  4375.46, 3948.75, 3949.65, 3815.68, 2690.1,  3177.36, 3770.18, 3077.21,
    2452.54, 2246.85, 3180.08, 3161.15, 3206.48, 2052.7,  2156.84, 3192.45, 3805.08, 4346.07,
    4360.21, 3907.17, 1785.38, 2477.22, 3003.36, 3540.95, 3390.24, 3200.76, 3442.32, 3849.23,
    3769.51, 3542.96, 2825.2,  2680.61, 2743.8,  4003.99, 4686.96, 4879.01, 1112.18, 1371.16,
    2196.92, 2180.81, 2407,    2322.53, 2373.88, 2960.16, 4079,    4195.93, 4066.32, 3809.63,
    2822.15, 3006.56, 3141.3,  4481.55};

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
