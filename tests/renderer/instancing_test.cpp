#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "renderer/acceleration/embree_scene.h"
#include "renderer/materials/bark_texture.h"
#include "renderer/transport/render.h"
#include "tests/support/single_item.h"
#include "trees/mesher.h"

namespace landsim::renderer {
namespace {

// A prototype that is a single vertical square (2 m wide, 4 m tall) in the x = 0 plane,
// facing +x, in the given group.
TreePrototype panel(trees::Group group) {
  TreePrototype p;
  trees::TriangleSet& t = p.geometry.group(group).triangles;
  t.vertices = {{0, -1, 0}, {0, 1, 0}, {0, 1, 4}, {0, -1, 4}};
  t.normals.assign(4, Vec3f{1, 0, 0});
  t.indices = {0, 1, 2, 0, 2, 3};
  test::make_single_item(p.geometry.group(group));
  p.bark_albedo = {0.5f, 0.5f, 0.5f};
  p.leaf_reflectance = {0.2f, 0.2f, 0.2f};
  p.leaf_transmittance = {0.0f, 0.0f, 0.0f};
  return p;
}

Scene base_scene() {
  Scene s;
  s.sun.direction = normalize(Vec3{1.0, 0.0, 0.3});
  s.settings.spp = 4;
  s.settings.max_bounces = 0;  // direct light only: easy to compare
  return s;
}

TEST(Instancing, LeavesTakeTheColourOfTheirVigour) {
  // Two leaf panels side by side: the left one (triangles 0-1, +y side) of vigour 0, the
  // right one of vigour 1.
  Scene s = base_scene();
  TreePrototype p = panel(trees::Group::leaves);
  trees::GroupGeometry& leaves = p.geometry.group(trees::Group::leaves);
  leaves.triangles.vertices = {{0, 0, 0},  {0, 1, 0}, {0, 1, 4}, {0, 0, 4},
                               {0, -1, 0}, {0, 0, 0}, {0, 0, 4}, {0, -1, 4}};
  leaves.triangles.normals.assign(8, Vec3f{1, 0, 0});
  leaves.triangles.indices = {0, 1, 2, 0, 2, 3, 4, 5, 6, 4, 6, 7};
  leaves.item_count = 2;
  leaves.item_triangle_end = {2, 4};
  leaves.item_vigour = {0.0f, 1.0f};
  p.leaf_weak_tint = {2.0f, 1.0f, 0.5f};
  s.prototypes.push_back(p);
  s.instances.push_back({0, {10.0, 0.0, 0.0}, 0.0, 1.0});
  const View view{"v", {0.0, 0.0, 2.0}, {1.0, 0.0, 2.0}, 30.0, 64, 64};
  const Film film = Renderer(s).render(view, {});
  int weak = 0, full = 0;
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) {
      if (film.object(x, y) != static_cast<std::uint8_t>(ObjectClass::leaf)) continue;
      const Vec3f a = film.albedo(x, y);
      if (x < 30) {  // +y: the weak panel
        ++weak;
        EXPECT_NEAR(a.x, 0.4f, 1e-4);
        EXPECT_NEAR(a.z, 0.1f, 1e-4);
      } else if (x > 33) {
        ++full;
        EXPECT_NEAR(a.x, 0.2f, 1e-4);
        EXPECT_NEAR(a.z, 0.2f, 1e-4);
      }
    }
  EXPECT_GT(weak, 50);
  EXPECT_GT(full, 50);
}

TEST(Instancing, InstancesAppearWhereTheirTransformPutsThem) {
  Scene s = base_scene();
  s.prototypes.push_back(panel(trees::Group::trunk));
  s.instances.push_back({0, {20.0, 5.0, 0.0}, 0.0, 1.0});
  s.instances.push_back({0, {40.0, -5.0, 0.0}, 0.0, 2.0});  // twice as big
  const View view{"v", {0.0, 0.0, 2.0}, {1.0, 0.0, 2.0}, 60.0, 64, 64};
  const Film film = Renderer(s).render(view, {});
  // The near panel covers y in [4, 6] at x = 20: left of centre (the image's left is +y
  // when looking along +x). The far one covers y in [-7, -3] at x = 40: right of centre.
  int near = 0, far = 0;
  for (int y = 0; y < 64; ++y) {
    for (int x = 0; x < 64; ++x) {
      if (film.object(x, y) != static_cast<std::uint8_t>(ObjectClass::bark)) continue;
      const float d = film.depth(x, y);
      if (x < 32) {
        ++near;
        EXPECT_NEAR(d, 20.0f, 1.0f);
      } else {
        ++far;
        EXPECT_NEAR(d, 40.0f, 2.0f);
      }
    }
  }
  EXPECT_GT(near, 10);
  EXPECT_GT(far, 10);
}

TEST(Instancing, RotationAboutTheVerticalTurnsThePrototype) {
  // The same panel face-on, turned a quarter (edge-on to the camera) and a half turn (face-on
  // again, from behind): the edge-on one is a sliver at most, the others cover the same area.
  const auto bark_pixels = [](double heading) {
    Scene s = base_scene();
    s.prototypes.push_back(panel(trees::Group::trunk));
    s.instances.push_back({0, {20.0, 0.0, 0.0}, heading, 1.0});
    const View view{"v", {0.0, 0.0, 2.0}, {1.0, 0.0, 2.0}, 30.0, 32, 32};
    const Film film = Renderer(s).render(view, {});
    int bark = 0;
    for (int y = 0; y < 32; ++y)
      for (int x = 0; x < 32; ++x)
        bark += film.object(x, y) == static_cast<std::uint8_t>(ObjectClass::bark);
    return bark;
  };
  const int face_on = bark_pixels(0.0);
  EXPECT_GT(face_on, 50);  // 2 m x 4 m at 20 m: about 6 x 12 pixels
  EXPECT_LT(bark_pixels(std::numbers::pi / 2.0), 8);
  EXPECT_NEAR(bark_pixels(std::numbers::pi), face_on, 0.05 * face_on);
}

double mean_luminance_of(const Film& film, ObjectClass object) {
  double sum = 0.0;
  int n = 0;
  for (int y = 0; y < film.height(); ++y) {
    for (int x = 0; x < film.width(); ++x) {
      if (film.object(x, y) != static_cast<std::uint8_t>(object)) continue;
      sum += film.luminance(x, y);
      ++n;
    }
  }
  return n > 0 ? sum / n : 0.0;
}

TEST(Instancing, LeavesTransmitSunlightToTheirShadedSide) {
  // The camera sees the leaf panel's side facing away from the sun.
  Scene s = base_scene();
  s.sun.direction = normalize(Vec3{1.0, 0.0, 0.2});  // behind the panel, seen from the camera at -x
  TreePrototype opaque = panel(trees::Group::leaves);
  TreePrototype translucent = panel(trees::Group::leaves);
  translucent.leaf_transmittance = {0.15f, 0.15f, 0.15f};
  const View view{"v", {0.0, 0.0, 2.0}, {1.0, 0.0, 2.0}, 20.0, 32, 32};
  s.settings.degradation = false;  // a hand-made leaf has no disc for far ranges
  s.prototypes = {opaque};
  s.instances = {{0, {20.0, 0.0, 0.0}, 0.0, 1.0}};
  const double dark = mean_luminance_of(Renderer(s).render(view, {}), ObjectClass::leaf);
  s.prototypes = {translucent};
  const double lit = mean_luminance_of(Renderer(s).render(view, {}), ObjectClass::leaf);
  EXPECT_GT(lit, dark + 0.05);
}

TEST(Instancing, BarkTextureWrapsAroundTheStem) {
  // A vertical stem of radius 1 m through the mesher (which gives it texture coordinates)
  // and a texture white on its first half around, black on the second.
  trees::TreeSkeleton skeleton;
  trees::StemSkeleton stem;
  for (int i = 0; i < 3; ++i) stem.sections.push_back({{0, 0, 2.0 * i}, {0, 0, 1}, {1, 0, 0}, 1.0});
  skeleton.stems.push_back(stem);
  trees::MeshResolution res;
  res.ring_points[0] = 32;
  Scene s = base_scene();
  TreePrototype p;
  p.geometry = trees::mesh_tree(skeleton, res);
  p.bark_albedo = {0.5f, 0.5f, 0.5f};
  std::vector<float> texels(3 * 8, 0.0f);
  std::fill(texels.begin(), texels.begin() + 3 * 4, 1.0f);  // u in [0, 0.5) white
  p.bark_texture = std::make_shared<const BarkTexture>(TextureImage(8, 1, texels));
  s.prototypes = {p};
  s.instances = {{0, {20.0, 0.0, 0.0}, 0.0, 1.0}};
  const View view{"v", {0.0, 0.0, 2.0}, {20.0, 0.0, 2.0}, 20.0, 48, 32};
  const Film textured = Renderer(s).render(view, {});
  float lo = 10.0f, hi = 0.0f;
  int bark = 0;
  for (int y = 0; y < 32; ++y) {
    for (int x = 0; x < 48; ++x) {
      if (textured.object(x, y) != static_cast<std::uint8_t>(ObjectClass::bark)) continue;
      ++bark;
      lo = std::min(lo, textured.albedo(x, y).x);
      hi = std::max(hi, textured.albedo(x, y).x);
    }
  }
  ASSERT_GT(bark, 50);
  // The texture is normalised to mean 1: white halves become twice the albedo, black none.
  EXPECT_NEAR(hi, 1.0f, 0.05f);
  EXPECT_LT(lo, 0.05f);
}

}  // namespace
}  // namespace landsim::renderer
