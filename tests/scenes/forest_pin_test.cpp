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
    7930.69, 7762.63, 7659.97, 7604.1,  7609.53, 7688.65, 7848.81, 8093.87, 8425.23, 8864.87,
    9399.38, 10017.5, 10722.2, 11520.5, 12345,   13235.4, 9023.77, 8882.99, 8792.01, 8753.69,
    8767.54, 8865.09, 9057.92, 9363.12, 9752.83, 10252.6, 10856.9, 11554.9, 12305.9, 13156.6,
    14059.4, 14931.7, 9748.28, 9649.14, 9587.22, 9586.32, 9655.04, 9802,    10047.5, 10417.3,
    10883.4, 11449.1, 12110,   12848.7, 13663.5, 14522.8, 15412.1, 16321.1, 9626.4,  9529.49,
    9456.59, 9451.99, 9518.73, 9665.28, 8184.39, 6928.78, 6986.21, 8655.4,  11231.1, 12697.8,
    12694.9, 11973.9, 11950.9, 14258.4, 9513.75, 9405.65, 8364.16, 7387.68, 5383.11, 3295.75,
    2103.98, 1877.61, 2075.82, 2400.23, 3243.42, 4085.15, 4077.07, 3971.96, 4743.47, 4986.5,
    3998.94, 3493.5,  2819.18, 2251.66, 2015.09, 2131.89, 2637.97, 2338.12, 1795.67, 2027.51,
    2401.73, 3800.33, 4359.84, 3859.69, 3865.11, 3766.09, 2669.71, 3263.01, 3796.28, 3143.74,
    2557.31, 2307.7,  3102.96, 3181.96, 3168.05, 2027.46, 2136.86, 3258.15, 3787.18, 4266.23,
    4356.05, 3859.56, 1789.61, 2424.72, 2910.03, 3419.08, 3384.7,  3216.91, 3455.33, 3838.66,
    3770.57, 3671.95, 2850.7,  2649.78, 2712.88, 3958.27, 4621.16, 4854.59, 1152.5,  1457.48,
    2296.01, 2354.06, 2627.69, 2491.78, 2518.55, 3247.64, 4289.93, 4423.04, 4154.1,  3866.9,
    2819.46, 2991.42, 3182.02, 4471.73};

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
