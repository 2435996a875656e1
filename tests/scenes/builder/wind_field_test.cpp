// The wind over the terrain (scenes/builder/wind_field.h) and the forests it moves: gusts travel
// downwind, trees lean with the local wind, variants sway in phase groups, and a frame is
// the same whatever was built before it.
#include "scenes/builder/wind_field.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <set>

#include "renderer/transport/render.h"
#include "scenes/builder/scene_builder.h"
#include "tests/support/temp_dir.h"

namespace landsim::scenes {
namespace {

using landsim::testing::source_file;
using landsim::testing::TempDir;

WindSettings breeze() {
  WindSettings w;
  w.speed = 6.0;
  w.gust = 8.0;
  w.direction_deg = 300.0;  // from the west-north-west
  w.gust_scale = 25.0;
  return w;
}

TEST(WindField, GustsTravelDownwindAtTheWindsSpeed) {
  const WindSettings w = breeze();
  const Vec3 d = downwind(w);
  // From 300 degrees: toward 120 degrees, east-south-east.
  EXPECT_NEAR(d.x, std::sin(120.0 * std::numbers::pi / 180.0), 1e-12);
  EXPECT_NEAR(d.y, std::cos(120.0 * std::numbers::pi / 180.0), 1e-12);
  double lo = 1e9, hi = -1e9;
  for (int k = 0; k < 200; ++k) {
    const double x = 13.0 * k, y = -7.0 * k, t = 0.37 * k;
    const double here = local_wind(w, x, y, t);
    // The same gust 3 s later, 3 s x speed further downwind.
    EXPECT_NEAR(local_wind(w, x + d.x * w.speed * 3.0, y + d.y * w.speed * 3.0, t + 3.0), here,
                1e-9);
    lo = std::min(lo, here);
    hi = std::max(hi, here);
  }
  EXPECT_GE(lo, w.speed);
  EXPECT_LE(hi, w.speed + w.gust);
  EXPECT_GT(hi - lo, 0.3 * w.gust);  // the gusts vary
}

TEST(WindField, TreesLeanDownwindByTheSquareOfTheLocalWind) {
  const WindSettings w = breeze();
  renderer::TreeInstance t;
  t.lean = tree_lean(w, 40.0, 10.0, 2.0);
  const Vec3 top = t.apply_lean({0.0, 0.0, 1.0});
  const Vec3 d = downwind(w);
  EXPECT_GT(top.x * d.x + top.y * d.y, 0.0);           // toward where the wind blows
  EXPECT_NEAR(top.x * d.y - top.y * d.x, 0.0, 1e-12);  // and nowhere else
  const double v = local_wind(w, 40.0, 10.0, 2.0);
  EXPECT_NEAR(length(t.lean) * 180.0 / std::numbers::pi, kLeanPerSpeed2 * v * v, 1e-9);
  EXPECT_EQ(length(tree_lean(WindSettings{}, 40.0, 10.0, 2.0)), 0.0);  // calm: upright
}

std::string forest(const std::string& wind) {
  return "[terrain]\nelevation = \"" + source_file("data/terrain/volcano.asc").string() +
         "\"\n[sun]\nelevation = 40\nazimuth = 200\n[[views]]\nname = \"v\"\n"
         "position = [300.0, -100.0, 400.0]\ntarget = [300.0, 300.0, 150.0]\n"
         "[[species]]\nbit = 0\nfile = \"" +
         source_file("data/species/quaking_aspen.toml").string() +
         "\"\nvariants = 2\ndensity_per_ha = 40\ncover = \"everywhere\"\n[render]\nquality = "
         "0.3\n" +
         wind;
}

const char* const kWind =
    "[wind]\nspeed = 6.0\ngust = 8.0\ndirection = 300.0\ngust_scale = 25.0\nphase_groups = 3\n";

TEST(WindField, AVariantSwaysInPhaseGroupsAndNeighboursLeanAlike) {
  TempDir dir;
  const Scenario s = load_scenario(dir.write("w.toml", forest(kWind)));
  const renderer::Scene scene = build_scene(s, 1.0);
  // Two variants, three groups each, every one in use among hundreds of trees.
  ASSERT_GT(scene.instances.size(), 200u);
  EXPECT_EQ(scene.prototypes.size(), 6u);
  // The groups of one variant are the same tree in other poses.
  const auto& a = scene.prototypes[0].geometry.group(trees::Group::leaves).triangles.vertices;
  const auto& b = scene.prototypes[1].geometry.group(trees::Group::leaves).triangles.vertices;
  ASSERT_EQ(a.size(), b.size());
  EXPECT_NE(a, b);
  // Leans: neighbours (within 5 m) alike, trees 10 gust scales apart unalike.
  double near = 0.0, far = 0.0;
  int near_pairs = 0, far_pairs = 0;
  for (std::size_t i = 0; i < scene.instances.size(); ++i)
    for (std::size_t j = i + 1; j < scene.instances.size(); ++j) {
      const auto& p = scene.instances[i];
      const auto& q = scene.instances[j];
      const double d = std::hypot(p.position.x - q.position.x, p.position.y - q.position.y);
      const double diff = std::abs(length(p.lean) - length(q.lean));
      if (d < 5.0) {
        near += diff;
        ++near_pairs;
      } else if (d > 250.0) {
        far += diff;
        ++far_pairs;
      }
    }
  ASSERT_GT(near_pairs, 5);
  ASSERT_GT(far_pairs, 100);
  EXPECT_LT(near / near_pairs, 0.3 * (far / far_pairs));
  // Phase groups come in patches: trees of one variant within 5 m mostly sway in one group,
  // far apart mostly not (three groups: a third by chance).
  int near_same = 0, near_count = 0, far_same = 0, far_count = 0;
  for (std::size_t i = 0; i < scene.instances.size(); ++i)
    for (std::size_t j = i + 1; j < scene.instances.size(); ++j) {
      const auto& p = scene.instances[i];
      const auto& q = scene.instances[j];
      if (p.prototype / 3 != q.prototype / 3) continue;  // another variant
      const double d = std::hypot(p.position.x - q.position.x, p.position.y - q.position.y);
      const bool same = p.prototype == q.prototype;
      if (d < 5.0) {
        near_same += same;
        ++near_count;
      } else if (d > 250.0) {
        far_same += same;
        ++far_count;
      }
    }
  ASSERT_GT(near_count, 3);
  EXPECT_GT(near_same, near_count * 7 / 10);
  EXPECT_LT(far_same, far_count * 6 / 10);
}

TEST(WindField, AFrameIsTheSameWhateverWasBuiltBeforeIt) {
  TempDir dir;
  const Scenario s = load_scenario(dir.write("w.toml", forest(kWind)));
  const renderer::Scene first = build_scene(s, 2.0);
  build_scene(s, 0.5);
  const renderer::Scene again = build_scene(s, 2.0);
  ASSERT_EQ(first.prototypes.size(), again.prototypes.size());
  for (std::size_t k = 0; k < first.prototypes.size(); ++k)
    EXPECT_EQ(first.prototypes[k].geometry.group(trees::Group::leaves).triangles.vertices,
              again.prototypes[k].geometry.group(trees::Group::leaves).triangles.vertices);
  ASSERT_EQ(first.instances.size(), again.instances.size());
  for (std::size_t i = 0; i < first.instances.size(); ++i)
    EXPECT_EQ(first.instances[i].lean, again.instances[i].lean);
  // Without wind: one group per variant, every tree upright.
  const renderer::Scene calm = build_scene(load_scenario(dir.write("c.toml", forest(""))), 2.0);
  EXPECT_EQ(calm.prototypes.size(), 2u);
  ASSERT_GT(calm.instances.size(), 10u);
  for (const renderer::TreeInstance& t : calm.instances) ASSERT_FALSE(t.leans());
}

TEST(WindField, RangeDegradationKeepsWorkingInEveryFrame) {
  TempDir dir;
  // The forest seen from afar: far trees are drawn at coarser levels in windy frames too.
  const Scenario s = load_scenario(dir.write(
      "w.toml", forest(kWind) + "[[views]]\nname = \"far\"\nposition = [300.0, -900.0, 500.0]\n"
                                "target = [300.0, 400.0, 150.0]\nwidth = 96\nheight = 64\n"));
  for (const double t : {0.5, 2.0}) {
    const renderer::Scene scene = build_scene(s, t);
    const renderer::Film film = renderer::Renderer(scene).render(scene.views[1], {});
    std::uint32_t coarsest = 0;
    int trees = 0;
    for (int y = 0; y < film.height(); ++y)
      for (int x = 0; x < film.width(); ++x)
        if (film.object(x, y) == 2 || film.object(x, y) == 3) {
          ++trees;
          coarsest = std::max(coarsest, film.level(x, y));
        }
    EXPECT_GT(trees, 20) << t;
    EXPECT_GT(coarsest, 0u) << "frame " << t << ": far trees at full detail";
  }
}

}  // namespace
}  // namespace landsim::scenes
