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
//
// Re-pasted: issue 70, the haze table's quadrature along rays into the sky exact for a
// constant source at any depth (toward the horizon it had lost most of the light) and its
// strategies weighed by the paths each draws: the sky's blocks 0.01-0.05% brighter, the
// forest's moved by the table's other frozen noise (0.16% on average, each within 1.5%).
// Before that: issue 57's fourth session, the haze table's cells sharing their height's paths
// (each path weighed for every cell by the balance heuristic): the table's frozen noise
// halved, its blocks moved by 0.25% on average (each within 2%), as its old noise allowed.
// Before that: issue 57's third session, open surfaces' skylight through a closed-form control
// variate and the first vertex's shadow rays unrouletted: same mean (the ground's blocks
// 0.08% apart on average, each within 3%), the sky's blocks within 0.05% (the haze table's
// paths take the same estimators, so its cells hold other frozen noise).
// Before that: issue 57 again, the hazy sky one light for surfaces (the sky transmitted, the
// haze's light and its aureole sampled together by their luminance, one shadow ray): same
// mean, other noise (the forest's blocks moved by up to 3%, the sky's not at all).
// Before that: issue 60, Weber & Penn's negative nDownAngleV sweeps as the paper prints it
// (through ShapeRatio 0): the forest's black tupelo, sassafras and eastern cottonwood hold
// their top main branches higher (35 of 144 blocks moved).
// Before that: issue 58, a haze segment's path goes on with the segment's mean scattered share
// (it was its extinguished share): the haze table's cells, traced that way, hold other frozen
// noise, and the hazy band along the horizon moved by 0.6-0.9% (7 blocks), the rest by less.
// Before that: issue 57, the haze a participating medium and paths ended by roulette alone:
// the haze scatters sunlight down and into the view (its further light tabulated), the air
// scatters between the camera and the forest, the crowns' interreflections no longer cut at
// 4 bounces.
// Before that: session 19, the Sobol sampler made the default (docs/PERFORMANCE.md "Time to
// E64"); only the noise moved (the sky's blocks by under 0.5%, the forest's by a few percent).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <string>

#include "renderer/transport/render.h"
#include "scenes/builder/scene_builder.h"
#include "scenes/scenario/scenario.h"
#include "tests/support/temp_dir.h"

namespace landsim::scenes {
namespace {

constexpr int kCols = 16, kRows = 9, kBlock = 6;  // 96 x 54 pixels

// Luminance means of kRows x kCols blocks of kBlock x kBlock pixels, row by row.
// A row of the image a line.
// clang-format off
constexpr std::array<double, kCols* kRows> kPinned = {
7149.24, 7090.77, 7063.28, 7075.93, 7153.97, 7306.49, 7521.05, 7805.32, 8169.21, 8628.39, 9238, 9948.57, 10747.5, 11641.7, 12616.3, 13655.6,
7901.4, 7884.86, 7902.24, 7960.34, 8079.03, 8286.85, 8552.39, 8888.1, 9307.42, 9825.43, 10510, 11294.1, 12160, 13095.1, 14101.1, 15145.2,
7607.95, 7689.6, 7817.38, 7984.34, 8211.76, 8525.06, 8887.1, 9316.9, 9798.93, 10344.7, 11126.5, 11973.9, 12875.7, 13836.5, 14822.8, 15843.8,
5881.35, 5932.78, 6039.36, 6171.7, 6341.73, 6640.89, 6122.07, 5591.61, 5701.01, 7047.83, 8485.04, 9469.16, 9802.27, 9837.74, 10353.6, 11974.1,
4343.54, 4324.14, 4114.82, 3814.87, 3066.14, 2489.93, 1767.49, 1805.72, 1938.76, 2070.88, 3182.29, 3289.63, 3712.02, 3634.5, 4333.98, 4583.1,
2822.32, 3194.27, 2944.11, 1987.22, 1870.28, 2136.38, 2465.25, 2142.47, 1576.22, 1728.16, 2094.08, 3675.82, 3984.4, 3388.12, 3270.12, 3101.25,
2881.23, 3404.71, 4112.78, 3200.33, 2357.05, 2109.77, 3258.68, 3167.62, 3277.88, 1670.72, 1684.39, 2872.03, 3416.64, 3947.61, 3843.58, 2969.82,
1845.45, 2606.6, 3235.46, 3755.96, 3640.9, 3463.61, 3716.61, 4139.76, 3838.94, 3483.38, 2629.59, 2212.11, 2156.71, 3528.05, 4196.35, 4171.44,
1118.51, 1447.2, 2331.73, 2360.03, 2541.08, 2493.96, 2558.87, 3313.04, 4442.63, 4464.2, 4047.86, 3470.29, 2191.46, 2296.59, 2433.28, 3701.8,
};
// clang-format on

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
