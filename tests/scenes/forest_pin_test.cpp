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
    8145.7,  7972.88, 7866.59, 7807.46, 7810.51, 7888.1,  8047.74, 8293.36, 8626.25, 9068.77,
    9607.21, 10229.8, 10940.4, 11745.5, 12576.6, 13474.4, 9277.29, 9132.93, 9038.97, 8998.1,
    9009.62, 9106.04, 9298.54, 9604.83, 9996.21, 10499,   11107.3, 11810.4, 12566.8, 13423.8,
    14333.3, 15211.9, 10035,   9934.6,  9871.29, 9869.48, 9937.93, 10084.9, 10331,   10702.5,
    11170.8, 11739.4, 12403.5, 13146.4, 13965.3, 14828.9, 15722.9, 16636.3, 9917.01, 9819.39,
    9745.98, 9741.16, 9808.05, 9955.2,  8417.56, 7118.38, 7169.72, 8856.87, 11511.8, 13002.1,
    12989.4, 12237.6, 12174.4, 14548.6, 9804.42, 9695.58, 8622.96, 7619.94, 5567.61, 3381.62,
    2168.07, 1936.38, 2109.01, 2440.88, 3317.32, 4136.33, 4141.68, 4090.1,  4860.94, 5069.58,
    4057.87, 3541,    2870.56, 2297.3,  2027.46, 2178.95, 2690.24, 2366.17, 1828.6,  2079.47,
    2453.13, 3856.36, 4444.42, 3984.42, 3958.36, 3842.92, 2679.49, 3317,    3843.39, 3227.55,
    2620.54, 2324.88, 3193.36, 3266.85, 3259.68, 2070.22, 2194.48, 3254.15, 3835.49, 4398.14,
    4445.59, 3933.15, 1865.86, 2532.96, 3023,    3569.39, 3465.89, 3212.98, 3453.51, 3912.44,
    3879.66, 3658.53, 2864.56, 2705.1,  2763.94, 4067.91, 4729.02, 4960.6,  1214.86, 1531.61,
    2368.24, 2294.95, 2517.13, 2433.04, 2528.05, 3160.77, 4249.02, 4317.86, 4105.91, 3825.97,
    2848.57, 3017.2,  3235.76, 4547.68};

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
