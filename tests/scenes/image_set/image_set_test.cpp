// An image set rendered through the library, no program spawned: the files and the
// manifest, resume keeping finished images, a task index, a stop before anything is built.
#include "scenes/image_set/image_set.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <set>
#include <string>

#include "core/input_error.h"
#include "renderer/output/image_output.h"
#include "renderer/spectra/colour_matching.h"
#include "tests/support/rendered_set.h"
#include "tests/support/temp_dir.h"

namespace landsim::scenes {
namespace {

using landsim::testing::TempDir;

// One view `width` x `height` of the bare volcano at 1 spp, and `more` after its [render].
Scenario volcano_view(int width, int height, const std::string& more) {
  const std::string text =
      "[terrain]\nelevation = \"" +
      landsim::testing::source_file("data/terrain/volcano.asc").string() +
      "\"\n[sun]\nelevation = 30\nazimuth = 300\n[[views]]\nname = \"v\"\n"
      "position = [500.0, 900.0, 330.0]\ntarget = [280.0, 280.0, 130.0]\nwidth = " +
      std::to_string(width) + "\nheight = " + std::to_string(height) + "\n[render]\nspp = 1\n" +
      more;
  return parse_scenario(text, "set.toml", ".");
}

// Two frames of one 32 x 18 view of the bare volcano at 1 spp.
Scenario two_frames() { return volcano_view(32, 18, "frames = [0.0, 1.0]\n"); }

nlohmann::json manifest_in(const std::filesystem::path& dir) {
  return nlohmann::json::parse(landsim::testing::read_file(dir / "manifest.json"));
}

TEST(ImageSet, RendersEveryImageWithItsPreviewAndTheManifest) {
  TempDir dir;
  ImageSetOptions o;
  o.out_dir = dir / "out";
  int written = 0;
  o.written = [&](const ImageReport& r) {
    ++written;
    EXPECT_TRUE(std::filesystem::exists(r.exr));
  };
  const ImageSetResult r = render_image_set(two_frames(), o);
  ASSERT_EQ(r.images.size(), 2u);
  EXPECT_EQ(written, 2);
  EXPECT_FALSE(r.stopped_at.has_value());
  EXPECT_GT(r.memory_estimate_bytes, 0u);
  for (const char* f : {"v_f0000.exr", "v_f0000.png", "v_f0001.exr", "v_f0001.png"})
    EXPECT_TRUE(std::filesystem::exists(o.out_dir / f)) << f;
  const nlohmann::json m = manifest_in(o.out_dir);
  EXPECT_TRUE(m["complete"].get<bool>());
  ASSERT_EQ(m["images"].size(), 2u);
  EXPECT_EQ(m["images"][1]["path"], "v_f0001.exr");
  EXPECT_EQ(m["images"][1]["time_s"], 1.0);
  EXPECT_EQ(r.images[1].frame_index, 1u);
  EXPECT_EQ(r.images[1].width, 32);
}

// Each image states its own error in the manifest (issue 72 item 3; docs/OUTPUTS.md): from
// its samples' spread, an upper bound under the Sobol sampler, null with one sample a pixel;
// a resumed set reads it back from the image's EXR.
TEST(ImageSet, TheManifestStatesEachImagesOwnError) {
  TempDir dir;
  ImageSetOptions o;
  o.out_dir = dir / "out";
  Scenario s = volcano_view(24, 16, "frames = [0.0, 1.0]\n");
  s.render.spp = 4;
  render_image_set(s, o);
  const nlohmann::json noise = manifest_in(o.out_dir)["images"][0]["noise"];
  ASSERT_TRUE(noise.is_object()) << noise;
  EXPECT_GT(noise["relative_mse"].get<double>(), 0.0);
  EXPECT_GT(noise["pixel_relative_se_p95"].get<double>(),
            noise["pixel_relative_se_median"].get<double>());
  EXPECT_LT(noise["frame_relative_se"].get<double>(),
            noise["pixel_relative_se_median"].get<double>());
  EXPECT_EQ(noise["mean_spp"].get<double>(), 4.0);
  EXPECT_TRUE(noise["upper_bound"].get<bool>());  // Sobol, the default
  std::filesystem::remove(o.out_dir / "v_f0001.exr");
  o.resume = true;
  render_image_set(s, o);
  EXPECT_EQ(manifest_in(o.out_dir)["images"][0]["noise"], noise);
  o.resume = false;
  o.out_dir = dir / "independent";
  s.render.sampler = SampleSequence::independent;
  render_image_set(s, o);
  EXPECT_FALSE(manifest_in(o.out_dir)["images"][0]["noise"]["upper_bound"].get<bool>());
  o.out_dir = dir / "one";
  render_image_set(two_frames(), o);
  EXPECT_TRUE(manifest_in(o.out_dir)["images"][0]["noise"].is_null());
}

// A randomised set estimates each image's scene before building it (issue 73): the program's
// own size in those estimates is the one measured before the first scene, not the process's
// size after it (which holds the freed scenes' memory the allocator keeps), so images whose
// draws build the same scene are estimated alike instead of growing image by image.
TEST(ImageSet, ARandomisedSetsEstimatesDoNotGrowWithTheImagesRendered) {
  TempDir dir;
  ImageSetOptions o;
  o.out_dir = dir / "out";
  const ImageSetResult r = render_image_set(
      volcano_view(64, 36, "[randomise]\nimages = 3\n\"sun.elevation\" = { range = [20, 70] }\n"),
      o);
  ASSERT_EQ(r.images.size(), 3u);
  ASSERT_EQ(r.memory_estimates_bytes.size(), 3u);
  EXPECT_EQ(r.memory_estimates_bytes[1], r.memory_estimates_bytes[0]);
  EXPECT_EQ(r.memory_estimates_bytes[2], r.memory_estimates_bytes[0]);
  EXPECT_EQ(r.memory_estimate_bytes, r.memory_estimates_bytes[0]);
}

TEST(ImageSet, ResumeKeepsFinishedImagesBitForBit) {
  TempDir dir;
  ImageSetOptions o;
  o.out_dir = dir / "out";
  render_image_set(two_frames(), o);
  const std::string first = landsim::testing::read_file(o.out_dir / "v_f0000.exr");
  std::filesystem::remove(o.out_dir / "v_f0001.exr");
  o.resume = true;
  const ImageSetResult again = render_image_set(two_frames(), o);
  EXPECT_EQ(again.skipped, 1u);
  ASSERT_EQ(again.images.size(), 1u);
  EXPECT_EQ(again.images[0].frame_index, 1u);
  EXPECT_EQ(landsim::testing::read_file(o.out_dir / "v_f0000.exr"), first);
  EXPECT_EQ(manifest_in(o.out_dir)["images"].size(), 2u);
}

TEST(ImageSet, ATaskIndexRendersOneImageAndNoManifest) {
  TempDir dir;
  ImageSetOptions o;
  o.out_dir = dir / "out";
  o.task_index = 1;
  const ImageSetResult r = render_image_set(two_frames(), o);
  ASSERT_EQ(r.images.size(), 1u);
  EXPECT_TRUE(std::filesystem::exists(o.out_dir / "v_f0001.exr"));
  EXPECT_FALSE(std::filesystem::exists(o.out_dir / "v_f0000.exr"));
  EXPECT_FALSE(std::filesystem::exists(o.out_dir / "manifest.json"));
  o.task_index = 2;
  EXPECT_THROW(render_image_set(two_frames(), o), InputError);
}

// Asked to stop before the first scene is built: nothing is built and nothing written.
TEST(ImageSet, AStopBeforeTheSceneWritesNothing) {
  TempDir dir;
  ImageSetOptions o;
  o.out_dir = dir / "out";
  o.stop = [] { return true; };
  const ImageSetResult r = render_image_set(two_frames(), o);
  ASSERT_TRUE(r.stopped_at.has_value());
  EXPECT_EQ(*r.stopped_at, "v_f0000");
  EXPECT_TRUE(r.stopped_before_tracing);
  EXPECT_TRUE(r.images.empty());
  EXPECT_FALSE(std::filesystem::exists(o.out_dir));
}

// A later image that cannot be written (its name taken by a directory) leaves the finished
// ones with a manifest that says the set is unfinished, and the error goes to the caller.
TEST(ImageSet, ALaterImageThatFailsLeavesAManifestOfTheFinishedOnes) {
  TempDir dir;
  ImageSetOptions o;
  o.out_dir = dir / "out";
  std::filesystem::create_directories(o.out_dir / "v_f0001.exr");
  EXPECT_ANY_THROW(render_image_set(two_frames(), o));
  const nlohmann::json m = manifest_in(o.out_dir);
  EXPECT_FALSE(m["complete"].get<bool>());
  ASSERT_EQ(m["images"].size(), 1u);
  EXPECT_EQ(m["images"][0]["path"], "v_f0000.exr");
}

TEST(ImageSet, CheckNamesTheMissingImagesAndWritesTheManifestWhenNoneAre) {
  TempDir dir;
  ImageSetOptions o;
  o.out_dir = dir / "out";
  render_image_set(two_frames(), o);
  std::filesystem::remove(o.out_dir / "manifest.json");
  std::filesystem::remove(o.out_dir / "v_f0001.png");
  EXPECT_EQ(check_image_set(two_frames(), o.out_dir), std::vector<std::string>{"v_f0001.png"});
  EXPECT_FALSE(std::filesystem::exists(o.out_dir / "manifest.json"));
  render_image_set(two_frames(), o);
  EXPECT_TRUE(check_image_set(two_frames(), o.out_dir).empty());
  EXPECT_EQ(manifest_in(o.out_dir)["images"].size(), 2u);
}

// The legend (docs/OUTPUTS.md) names every id the layers hold, and each layer's none: two
// species and a truck on the volcano, in the manifest and in the EXR alike.
TEST(ImageSet, TheLegendNamesEveryIdInTheLayers) {
  const auto data = [](const std::string& f) {
    return landsim::testing::source_file("data/" + f).string();
  };
  const std::string text =
      "[terrain]\nelevation = \"" + data("terrain/volcano.asc") +
      "\"\n[sun]\nelevation = 30\nazimuth = 300\n"
      "[[species]]\nbit = 0\nfile = \"" +
      data("species/quaking_aspen.toml") +
      "\"\nvariants = 2\ndensity_per_ha = 40\ncover = { rectangle = [250, 700, 290, 780] }\n"
      "[[species]]\nbit = 1\nfile = \"" +
      data("species/fanpalm.xml") +
      "\"\nvariants = 1\ndensity_per_ha = 40\ncover = { rectangle = [290, 700, 330, 780] }\n"
      "[[objects]]\nname = \"truck\"\nfile = \"" +
      data("objects/truck.obj") +
      "\"\nposition = [290, 690]\n"
      "[[views]]\nname = \"v\"\nposition = [290.0, 640.0, 140.0]\n"
      "target = [290.0, 740.0, 110.0]\nwidth = 64\nheight = 48\n[render]\nspp = 2\n";
  TempDir dir;
  ImageSetOptions o;
  o.out_dir = dir / "out";
  render_image_set(parse_scenario(text, "set.toml", "."), o);
  const nlohmann::json legend = manifest_in(o.out_dir)["legend"];
  renderer::ImageMetadata meta;
  const renderer::Film film = renderer::read_exr(o.out_dir / "v.exr", &meta);
  bool in_exr = false;
  for (const auto& [key, value] : meta)
    in_exr |= key == "legend" && nlohmann::json::parse(value) == legend;
  EXPECT_TRUE(in_exr);
  ASSERT_EQ(legend["species"]["values"].size(), 2u);
  EXPECT_EQ(legend["species"]["values"][1]["core"], "weber_penn");
  EXPECT_EQ(legend["target"]["values"][0]["name"], "truck");
  std::set<std::uint64_t> species_seen, targets_seen, classes_seen;
  for (int y = 0; y < film.height(); ++y)
    for (int x = 0; x < film.width(); ++x) {
      const auto s = film.species(x, y);
      if (s != legend["species"]["none"].get<std::uint64_t>()) species_seen.insert(s);
      if (film.target(x, y) != legend["target"]["none"].get<std::uint32_t>())
        targets_seen.insert(film.target(x, y));
      classes_seen.insert(film.object(x, y));
    }
  EXPECT_EQ(species_seen.size(), 2u);  // both species in view
  for (const auto s : species_seen) EXPECT_LT(s, legend["species"]["values"].size());
  EXPECT_EQ(targets_seen, (std::set<std::uint64_t>{1}));  // the truck, id 1
  for (const auto c : classes_seen)
    EXPECT_TRUE(legend["object"]["values"].contains(std::to_string(c))) << c;
}

}  // namespace
}  // namespace landsim::scenes

namespace landsim::scenes {
namespace {

// The manifest states the one atmosphere's optical depths at 550 nm from the lowest ground,
// what the sun's beam is dimmed by: each as worked out apart from the medium (Hansen and
// Travis 1974's Rayleigh depth of the sea-level column scaled by the U.S. Standard's
// pressure at the ground's altitude; 345.9 DU of ozone times its cross section at 550 nm;
// Koschmieder's 3.912 / V less the air's share, over the scale height), and the EXR says it.
TEST(ImageSet, TheManifestStatesTheAtmospheresOpticalDepths) {
  Scenario s = load_scenario(landsim::testing::source_file("scenes/examples/one_atmosphere.toml"));
  s.views[0].width = 16;
  s.views[0].height = 9;
  s.render.spp = 1;
  s.species.clear();
  s.grass.clear();
  const auto images = landsim::testing::render_in_memory(s);
  ASSERT_EQ(images.size(), 1u);
  const nlohmann::json e = nlohmann::json::parse(images[0].manifest_entry);
  const nlohmann::json& tau = e["settings"]["atmosphere"]["optical_depth_550nm"];
  // The volcano's lowest ground is about 95 m up: 98.9% of the sea-level pressure.
  const double rayleigh = 0.008569 / std::pow(0.55, 4) *
                          (1.0 + 0.0113 / (0.55 * 0.55) + 0.00013 / std::pow(0.55, 4)) * 0.989;
  EXPECT_NEAR(tau["rayleigh"].get<double>() / rayleigh, 1.0, 0.01) << tau.dump();
  EXPECT_NEAR(tau["ozone"].get<double>() / (345.86 * 2.6867e20 * 3.5e-25), 1.0, 0.01);
  EXPECT_NEAR(tau["aerosol"].get<double>() / ((3.912 / 15000.0 - 1.14e-5) * 600.0), 1.0, 0.01);
  EXPECT_EQ(e["settings"]["haze"], nullptr);
  bool stated = false;
  for (const auto& [key, value] : images[0].metadata)
    if (key == "haze") stated = value.find("aerosol visibility 15000 m") != std::string::npos;
  EXPECT_TRUE(stated);
}

// [render] atmosphere_layers: the image holds the atmosphere's parts, finished (the surface
// divided by the transmittance), and the surface's reflectance factor, in RGB and every band.
TEST(ImageSet, AtmosphereLayersAreFinishedInTheImage) {
  Scenario s = load_scenario(landsim::testing::source_file("scenes/examples/one_atmosphere.toml"));
  s.views[0].width = 16;
  s.views[0].height = 9;
  s.render.spp = 2;
  s.render.atmosphere_layers = true;
  s.species.clear();
  s.grass.clear();
  const auto images = landsim::testing::render_in_memory(s);
  ASSERT_EQ(images.size(), 1u);
  const renderer::Film& film = images[0].film;
  const auto plane = [&](const std::string& name) -> const std::vector<float>& {
    for (int b = 0; b < film.band_count(); ++b)
      if (film.band_name(b) == name) return film.band_data(b);
    ADD_FAILURE() << "no layer " << name;
    static const std::vector<float> none;
    return none;
  };
  for (const char* part : {"path", "transmittance", "surface", "direct", "diffuse", "reflectance"})
    for (const char* c : {"X", "Y", "Z"}) plane(std::string("atmosphere.") + part + "." + c);
  const std::vector<float>& path = plane("atmosphere.path.Y");
  const std::vector<float>& t = plane("atmosphere.transmittance.Y");
  const std::vector<float>& surface = plane("atmosphere.surface.Y");
  const std::vector<float>& reflectance = plane("atmosphere.reflectance.Y");
  ASSERT_EQ(path.size(), film.pixel_count());
  int ground = 0;
  for (int y = 0; y < film.height(); ++y)
    for (int x = 0; x < film.width(); ++x) {
      const std::size_t i = static_cast<std::size_t>(y * film.width() + x);
      const auto apparent = static_cast<float>(renderer::rec709_to_xyz(Vec3(film.rgb(x, y))).y);
      EXPECT_NEAR(path[i] + t[i] * surface[i], apparent, 1e-4f * std::abs(apparent) + 1e-3f);
      if (film.object(x, y) == static_cast<std::uint8_t>(renderer::ObjectClass::ground)) {
        ++ground;
        EXPECT_GT(t[i], 0.5f);  // a few hundred metres of 15 km visibility
      }
    }
  EXPECT_GT(ground, 0);
  double r = 0.0;
  for (float v : reflectance) r += v;
  EXPECT_GT(r, 0.0);
}

}  // namespace
}  // namespace landsim::scenes
