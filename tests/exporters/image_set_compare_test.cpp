// `landsim compare`'s library: two image sets, image by image.
#include "exporters/image_set_compare.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fstream>

#include "core/input_error.h"
#include "renderer/output/film.h"
#include "renderer/output/image_output.h"
#include "tests/support/temp_dir.h"

namespace landsim::exporters {
namespace {

using landsim::testing::TempDir;

// A small film: a gradient of radiance, ground below the middle row, sky above.
renderer::Film film(int w, int h, float gain = 1.0f, Vec3f normal = {0, 0, 1}) {
  renderer::Film f(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      renderer::PixelAovs a;
      const bool ground = y >= h / 2;
      a.depth = ground ? 10.0f + static_cast<float>(y) : std::numeric_limits<float>::infinity();
      a.normal = ground ? normal : Vec3f{};
      a.object = ground ? 1u : 0u;
      f.set(x, y,
            Vec3f{100.0f + static_cast<float>(x), 200.0f + static_cast<float>(y), 50.0f} * gain, a);
    }
  return f;
}

// A set in `dir`: the given views at frame 0, each image written as landsim writes it.
void write_set(const std::filesystem::path& dir,
               const std::vector<std::pair<std::string, renderer::Film>>& images) {
  std::filesystem::create_directories(dir);
  nlohmann::json list = nlohmann::json::array();
  for (const auto& [view, f] : images) {
    renderer::write_exr(f, dir / (view + ".exr"), {});
    list.push_back({{"path", view + ".exr"}, {"view", view}, {"frame_index", 0}});
  }
  std::ofstream(dir / "manifest.json") << nlohmann::json{{"images", list}}.dump();
}

// Tilted normals whose normalised dot product rounds below 1: equal normals are 0 degrees
// apart (acos of the rounded dot product read 5.8e-5 degrees for byte-identical sets).
TEST(ImageSetCompare, EqualTiltedNormalsAreNoAngleApart) {
  TempDir dir;
  for (const Vec3f n : {Vec3f{0.3f, 0.5f, 0.81f}, Vec3f{-0.62f, 0.11f, 0.77f}}) {
    write_set(dir / "a", {{"v", film(32, 16, 1.0f, n)}});
    write_set(dir / "b", {{"v", film(32, 16, 1.0f, n)}});
    const SetComparison c = compare_image_sets(dir / "a", dir / "b", {});
    ASSERT_EQ(c.images.size(), 1u);
    EXPECT_EQ(c.images[0].normal_mean_angle_deg, 0.0) << n.x << " " << n.y << " " << n.z;
  }
}

TEST(ImageSetCompare, IdenticalSetsPassWithNoDifference) {
  TempDir dir;
  write_set(dir / "a", {{"v", film(32, 16)}, {"w", film(32, 16, 0.5f)}});
  write_set(dir / "b", {{"v", film(32, 16)}, {"w", film(32, 16, 0.5f)}});
  const SetComparison c = compare_image_sets(dir / "a", dir / "b", {});
  EXPECT_TRUE(c.pass);
  ASSERT_EQ(c.images.size(), 2u);
  for (const ImageDifference& d : c.images) {
    EXPECT_TRUE(d.pass);
    EXPECT_EQ(d.luminance_mean_rel_diff, 0.0);
    EXPECT_EQ(d.object_mismatch, 0.0);
  }
}

TEST(ImageSetCompare, OneChangedImageIsReportedAndOnlyIt) {
  TempDir dir;
  write_set(dir / "a", {{"v", film(32, 16)}, {"w", film(32, 16)}});
  // w is 3% brighter in the new set.
  write_set(dir / "b", {{"v", film(32, 16)}, {"w", film(32, 16, 1.03f)}});
  const SetComparison c = compare_image_sets(dir / "b", dir / "a", {});
  EXPECT_FALSE(c.pass);
  ASSERT_EQ(c.images.size(), 2u);
  EXPECT_TRUE(c.images[0].pass);
  EXPECT_FALSE(c.images[1].pass);
  EXPECT_EQ(c.images[1].view, "w");
  EXPECT_NEAR(c.images[1].luminance_mean_rel_diff, 0.03, 1e-5);
  // A changed layer: the object class of a quarter of the pixels.
  renderer::Film changed = film(32, 16);
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 32; ++x) changed.object_data()[static_cast<std::size_t>(y) * 32 + x] = 3;
  write_set(dir / "c", {{"v", changed}, {"w", film(32, 16)}});
  const SetComparison l = compare_image_sets(dir / "c", dir / "a", {});
  EXPECT_FALSE(l.images[0].pass);
  EXPECT_NEAR(l.images[0].object_mismatch, 0.25, 1e-12);
  EXPECT_TRUE(l.images[1].pass);
  write_compare_reports(l, {}, dir / "c", dir / "a", dir / "report");
  EXPECT_TRUE(std::filesystem::exists(dir / "report" / "report.html"));
  std::ifstream in(dir / "report" / "report.json");
  EXPECT_FALSE(nlohmann::json::parse(in)["pass"].get<bool>());
}

TEST(ImageSetCompare, ImagesInOneSetOnlyAndSizeMismatchesFail) {
  TempDir dir;
  write_set(dir / "a", {{"v", film(32, 16)}, {"only_a", film(32, 16)}});
  write_set(dir / "b", {{"v", film(16, 8)}, {"only_b", film(32, 16)}});
  const SetComparison c = compare_image_sets(dir / "a", dir / "b", {});
  EXPECT_FALSE(c.pass);
  ASSERT_EQ(c.images.size(), 1u);
  EXPECT_TRUE(c.images[0].size_mismatch);
  EXPECT_FALSE(c.images[0].pass);
  EXPECT_EQ(c.only_in_a, std::vector<std::string>{"only_a f0"});
  EXPECT_EQ(c.only_in_b, std::vector<std::string>{"only_b f0"});
}

TEST(ImageSetCompare, AFolderWithoutManifestOrAnUnreadableImageIsRefused) {
  TempDir dir;
  write_set(dir / "a", {{"v", film(8, 8)}});
  std::filesystem::create_directories(dir / "empty");
  try {
    compare_image_sets(dir / "empty", dir / "a", {});
    FAIL() << "a folder without manifest.json was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("manifest.json"), std::string::npos) << e.what();
  }
  write_set(dir / "b", {{"v", film(8, 8)}});
  std::ofstream(dir / "b" / "v.exr") << "not an image";
  try {
    compare_image_sets(dir / "a", dir / "b", {});
    FAIL() << "an unreadable image was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("v.exr"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace landsim::exporters
