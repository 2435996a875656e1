// Object truth (renderer/output/object_truth.h) on scenes built from scenarios: what the manifest
// reports agrees with the film's target AOV, occlusion lowers the visible fraction, and a
// glTF and an OBJ of the same mesh render the same image.
#include "renderer/output/object_truth.h"

#include <gtest/gtest.h>

#include <fmt/format.h>

#include <cmath>

#include "renderer/transport/render.h"
#include "scenes/builder/scene_builder.h"
#include "tests/support/temp_dir.h"

namespace landsim::scenes {
namespace {

using testing::TempDir;

// A gentle slope of 40 x 40 cells of 5 m from (1000, 2000); the camera looks north-east at a
// car 20 m away.
std::string terrain(const TempDir& dir) {
  std::string text =
      "ncols 40\nnrows 40\nxllcorner 1000\nyllcorner 2000\ncellsize 5\nNODATA_value -9999\n";
  for (int r = 0; r < 40; ++r) {
    for (int c = 0; c < 40; ++c) text += std::to_string(100.0 + 0.1 * (39 - r) + 0.05 * c) + " ";
    text += "\n";
  }
  return dir.write("t.asc", text).string();
}

std::string scenario(const TempDir& dir, const std::string& file, const std::string& extra = "") {
  return "[terrain]\nelevation = \"" + terrain(dir) +
         "\"\n[sun]\nelevation = 40\nazimuth = 200\n"
         "[[views]]\nname = \"v\"\nposition = [1085.0, 2085.0, 105.0]\ntarget = [1100.0, 2100.0, "
         "102.0]\nfov = 30\nwidth = 96\nheight = 64\n[render]\nspp = 4\n"
         "[[objects]]\nname = \"car\"\nfile = \"" +
         testing::source_file("data/objects/" + file).string() +
         "\"\nposition = [1100, 2100]\nheading = 60\n" + extra;
}

renderer::Scene build(const TempDir& dir, const std::string& text) {
  return build_scene(load_scenario(dir.write("s.toml", text)));
}

renderer::Film render(const renderer::Scene& scene) {
  return renderer::Renderer(scene).render(scene.views[0], {});
}

// The film's pixels of object `target`, counted directly, and their bounds.
struct Count {
  std::uint64_t pixels = 0;
  renderer::PixelBox box{1 << 30, 1 << 30, -1, -1};
};
Count count(const renderer::Film& film, std::uint32_t target) {
  Count c;
  for (int y = 0; y < film.height(); ++y)
    for (int x = 0; x < film.width(); ++x)
      if (film.target(x, y) == target) {
        ++c.pixels;
        c.box = {std::min(c.box[0], x), std::min(c.box[1], y), std::max(c.box[2], x),
                 std::max(c.box[3], y)};
      }
  return c;
}

TEST(ObjectTruth, AnUnoccludedObjectIsWhollyVisibleAndItsCountsMatchTheFilm) {
  TempDir dir;
  const renderer::Scene scene = build(dir, scenario(dir, "car.obj"));
  const renderer::Film film = render(scene);
  const std::vector<renderer::ObjectTruth> truth =
      renderer::object_truth(scene, scene.views[0], film, false);
  ASSERT_EQ(truth.size(), 1u);
  const Count direct = count(film, 1);
  ASSERT_GT(direct.pixels, 100u);
  EXPECT_EQ(truth[0].name, "car");
  EXPECT_EQ(truth[0].visible_pixels, direct.pixels);
  ASSERT_TRUE(truth[0].bbox);
  EXPECT_EQ(*truth[0].bbox, direct.box);
  EXPECT_EQ(truth[0].footprint_pixels, direct.pixels);
  EXPECT_EQ(truth[0].visible_fraction, 1.0);
  // The object layer (the first sample) and the target layer (all samples) agree: a first
  // sample on the car makes it the pixel's target, a pixel wholly on it is classed object,
  // and a pixel none of whose samples hit it has no coverage. Edge pixels are partly covered.
  int partial = 0;
  for (int y = 0; y < film.height(); ++y)
    for (int x = 0; x < film.width(); ++x) {
      const bool first_on_car =
          film.object(x, y) == static_cast<std::uint8_t>(renderer::ObjectClass::object);
      EXPECT_TRUE(!first_on_car || film.target(x, y) == 1u);
      EXPECT_TRUE(film.coverage(x, y) < 1.0f || first_on_car);
      EXPECT_TRUE(film.target(x, y) != 0u || film.coverage(x, y) == 0.0f);
      partial += film.coverage(x, y) > 0.0f && film.coverage(x, y) < 1.0f;
    }
  EXPECT_GT(partial, 10);
  // Range: camera to the car's middle, about 21 m.
  EXPECT_NEAR(truth[0].range, std::hypot(15.0, 15.0, 3.0 - 0.7), 1.0);
}

TEST(ObjectTruth, AnObjectBehindATreeIsPartlyVisibleWithTheSameFootprint) {
  TempDir dir;
  const std::string aspen = "[[species]]\nbit = 0\nfile = \"" +
                            testing::source_file("data/species/quaking_aspen.toml").string() +
                            "\"\nvariants = 1\ndensity_per_ha = 20\ncover = \"everywhere\"\n";
  const renderer::Scene open = build(dir, scenario(dir, "car.obj"));
  renderer::Scene hidden = build(dir, scenario(dir, "car.obj", "clear_radius = 0\n" + aspen));
  ASSERT_FALSE(hidden.prototypes.empty());
  // One tree, its trunk on the line of sight 6 m in front of the car.
  const Vec3 car{hidden.objects[0].transform[9], hidden.objects[0].transform[10],
                 hidden.objects[0].transform[11]};
  const Vec3 towards =
      normalize(Vec3{hidden.views[0].position.x - car.x, hidden.views[0].position.y - car.y, 0.0});
  hidden.instances = {{0, car + towards * 6.0 - Vec3{0.0, 0.0, 0.3}, 0.0, 1.0}};
  const auto seen = renderer::object_truth(hidden, hidden.views[0], render(hidden), false);
  const auto clear = renderer::object_truth(open, open.views[0], render(open), false);
  EXPECT_EQ(seen[0].footprint_pixels, clear[0].footprint_pixels);
  EXPECT_GT(seen[0].visible_fraction, 0.0);
  EXPECT_LT(seen[0].visible_fraction, 0.95);
  EXPECT_EQ(clear[0].visible_fraction, 1.0);
}

TEST(ObjectTruth, ContrastIsNegativeForADarkObjectOnBrightGroundAndPositiveForAWhiteOne) {
  TempDir dir;
  const renderer::Scene dark = build(dir, scenario(dir, "car.obj"));
  const auto d = renderer::object_truth(dark, dark.views[0], render(dark), false);
  ASSERT_TRUE(d[0].contrast);
  EXPECT_LT(*d[0].contrast, -0.2);
  EXPECT_GT(d[0].background_pixels, 0u);
  EXPECT_GE(d[0].ring_width, 3);
  // Every material white: brighter than the ground (albedo 0.18).
  std::string white;
  for (const char* m : {"paint_red", "glass", "tyre", "chrome"})
    white += "[[objects.material]]\nname = \"" + std::string(m) + "\"\nalbedo = [0.9, 0.9, 0.9]\n";
  const renderer::Scene bright = build(dir, scenario(dir, "car.obj", white));
  const auto b = renderer::object_truth(bright, bright.views[0], render(bright), false);
  ASSERT_TRUE(b[0].contrast);
  EXPECT_GT(*b[0].contrast, 0.5);
  EXPECT_GT(b[0].luminance, d[0].luminance);
}

TEST(ObjectTruth, AnObjectCastsAShadowOnTheGround) {
  TempDir dir;
  // A low sun in the south-east: the car's shadow falls north-west, beside it in view.
  std::string with = scenario(dir, "car.obj");
  with.replace(with.find("elevation = 40\nazimuth = 200"), 28, "elevation = 15\nazimuth = 130");
  std::string without = with.substr(0, with.find("[[objects]]"));
  const renderer::Scene a = build(dir, with);
  const renderer::Scene b = build(dir, without);
  const renderer::Film fa = render(a), fb = render(b);
  // Ground pixels (no object in the way) at least 40% darker with the car than without it.
  int shadowed = 0;
  for (int y = 0; y < fa.height(); ++y)
    for (int x = 0; x < fa.width(); ++x)
      if (fa.target(x, y) == 0 && fa.luminance(x, y) < 0.6f * fb.luminance(x, y)) ++shadowed;
  EXPECT_GT(shadowed, 40);  // 84 when written
}

TEST(ObjectTruth, HazeLowersAnObjectsContrast) {
  TempDir dir;
  const renderer::Scene clear = build(dir, scenario(dir, "car.obj"));
  // A ground fog 20 m deep of 60 m visibility, water droplets (albedo 1): the car 25 m away
  // through an optical depth of 1.6. (A haze that deep 1200 m up would leave the scene dark:
  // its light scattered dozens of times, absorbed a little each time.)
  const renderer::Scene hazy =
      build(dir, scenario(dir, "car.obj") +
                     "[sky]\nmodel = \"gradient\"\n[haze]\nvisibility = 60.0\nscale_height = "
                     "20.0\nsingle_scattering_albedo = 1.0\n");
  const auto c = renderer::object_truth(clear, clear.views[0], render(clear), false);
  const auto h = renderer::object_truth(hazy, hazy.views[0], render(hazy), false);
  ASSERT_TRUE(c[0].contrast && h[0].contrast);
  EXPECT_LT(std::abs(*h[0].contrast), 0.7 * std::abs(*c[0].contrast));
  EXPECT_EQ(h[0].visible_pixels, c[0].visible_pixels);  // haze veils, it does not hide
}

TEST(ObjectTruth, AGltfAndAnObjOfTheSameMeshGiveTheSameImage) {
  TempDir dir;
  const renderer::Scene obj = build(dir, scenario(dir, "car.obj"));
  const renderer::Scene gltf = build(dir, scenario(dir, "car.gltf"));
  const renderer::Film a = render(obj), b = render(gltf);
  std::size_t same_target = 0;
  double diff = 0.0, sum = 0.0;
  for (int y = 0; y < a.height(); ++y)
    for (int x = 0; x < a.width(); ++x) {
      same_target += a.target(x, y) == b.target(x, y) ? 1 : 0;
      diff += std::abs(a.luminance(x, y) - b.luminance(x, y));
      sum += a.luminance(x, y);
    }
  EXPECT_GE(static_cast<double>(same_target), 0.999 * static_cast<double>(a.pixel_count()));
  EXPECT_LT(diff / sum, 1e-3);
  EXPECT_GT(count(a, 1).pixels, 100u);
}

// The car seen straight down from 60 m above the ground, and on a map view of 10 cm pixels
// (docs/CAMERAS.md): in both its truth holds (wholly visible, counts from the film) and its
// box is where the camera model puts the car's centre.
TEST(ObjectTruth, HoldsForANadirViewAndAMapView) {
  TempDir dir;
  const std::string views[] = {
      "[[views]]\nname = \"v\"\nposition = [1100.0, 2100.0]\naltitude_above_ground = 60\n"
      "direction = [0, 0, -1]\nfov = 10\nwidth = 96\nheight = 64\n",
      "[[views]]\nname = \"v\"\nposition = [1100.0, 2100.0, 400.0]\n"
      "projection = \"orthographic\"\npixel_size = 0.1\nwidth = 96\nheight = 64\n"};
  for (const std::string& view : views) {
    std::string text = scenario(dir, "car.obj");
    const auto from = text.find("[[views]]"), to = text.find("[render]");
    text.replace(from, to - from, view);
    const renderer::Scene scene = build(dir, text);
    const renderer::Film film = render(scene);
    const auto truth = renderer::object_truth(scene, scene.views[0], film, false);
    ASSERT_EQ(truth.size(), 1u);
    const Count direct = count(film, 1);
    ASSERT_GT(direct.pixels, 200u) << view;
    EXPECT_EQ(truth[0].visible_pixels, direct.pixels);
    EXPECT_EQ(truth[0].visible_fraction, 1.0);
    ASSERT_TRUE(truth[0].bbox);
    EXPECT_EQ(*truth[0].bbox, direct.box);
    // The car stands at the image centre (its box around pixel (48, 32)).
    EXPECT_LE((*truth[0].bbox)[0], 48);
    EXPECT_GE((*truth[0].bbox)[2], 47);
    EXPECT_LE((*truth[0].bbox)[1], 32);
    EXPECT_GE((*truth[0].bbox)[3], 31);
  }
}

// The car at 300 m, 1 km and 3 km, seen from the same direction through the same narrow lens:
// at 3 km it covers about a pixel, and its truth is still there. Its coverage summed over the
// image is its projected area in pixels, so it falls with the square of the range (within
// 5%; the samples' jitter is the only error).
TEST(ObjectTruth, ADistantCarKeepsItsSubPixelCoverage) {
  TempDir dir;
  double area_at_300 = 0.0;
  for (const double range : {300.0, 1000.0, 3000.0}) {
    const Vec3 car{1100.0, 2100.0, 103.6};
    const Vec3 camera = car + range * normalize(Vec3{-1.0, -1.0, 0.6});
    const std::string view = fmt::format(
        "[[views]]\nname = \"v\"\nposition = [{}, {}, {}]\ntarget = [{}, {}, {}]\nfov = 1.2\n"
        "width = 32\nheight = 32\n",
        camera.x, camera.y, camera.z, car.x, car.y, car.z);
    std::string text = scenario(dir, "car.obj");
    const auto from = text.find("[[views]]"), to = text.find("[render]");
    text.replace(from, to - from, view);
    text.replace(text.find("spp = 4"), 7, "spp = 512\nmax_bounces = 0");
    const renderer::Scene scene = build(dir, text);
    const auto truth = renderer::object_truth(scene, scene.views[0], render(scene), false);
    ASSERT_EQ(truth.size(), 1u);
    EXPECT_GT(truth[0].visible_pixels, 0u) << range;
    EXPECT_TRUE(truth[0].bbox) << range;
    EXPECT_NEAR(truth[0].visible_coverage, truth[0].footprint_coverage,
                0.02 * truth[0].footprint_coverage)
        << range;  // nothing hides it
    const double area = truth[0].visible_coverage * (range / 300.0) * (range / 300.0);
    if (range == 300.0) area_at_300 = area;
    EXPECT_NEAR(area / area_at_300, 1.0, 0.05) << range << " m: " << truth[0].visible_coverage;
  }
}

// The car's oriented box (its heading of 60 degrees, on a gentle slope) and truncation: in
// the frame, none; with the principal point moved so that the car's centre is on the right
// edge, about half of it is beyond the frame, apart from occlusion (none here).
TEST(ObjectTruth, TheBoxAndTruncationAreTheObjectsOwn) {
  TempDir dir;
  const renderer::Scene scene = build(dir, scenario(dir, "car.obj"));
  const auto truth = renderer::object_truth(scene, scene.views[0], render(scene), false);
  ASSERT_EQ(truth.size(), 1u);
  const renderer::ObjectBox& b = truth[0].box;
  EXPECT_NEAR(b.heading_deg, 60.0, 1.0);
  EXPECT_LT(std::abs(b.pitch_deg), 3.0);
  EXPECT_LT(std::abs(b.roll_deg), 3.0);
  EXPECT_GT(b.size.y, b.size.x);  // a car is longer than wide
  EXPECT_NEAR(length(b.centre_camera), truth[0].range, 0.05);
  EXPECT_GT(b.centre_camera.z, 0.0);  // ahead of the camera
  ASSERT_TRUE(truth[0].truncation);
  EXPECT_NEAR(*truth[0].truncation, 0.0, 1e-9);
  renderer::Scene shifted = scene;
  // The target (the car) projects at width / 2 + principal_x: the right edge.
  shifted.views[0].lens.principal_x = 0.5 * shifted.views[0].width;
  const auto cut = renderer::object_truth(shifted, shifted.views[0], render(shifted), false);
  ASSERT_TRUE(cut[0].truncation);
  EXPECT_GT(*cut[0].truncation, 0.3);
  EXPECT_LT(*cut[0].truncation, 0.7);
  EXPECT_NEAR(cut[0].visible_fraction, 1.0, 1e-9);  // truncation is not occlusion
}

}  // namespace
}  // namespace landsim::scenes
