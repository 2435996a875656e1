// `landsim render` with [sensor] and `landsim sense` (docs/SENSOR.md): digital numbers beside
// each EXR, the sensor model, irradiance and reflectance in the manifest and the EXR; sense
// reproduces the render's numbers, re-noises them with another seed, and refuses a sensor
// whose channels were not rendered.
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdint>
#include <vector>

#include "tests/support/run_program.h"
#include "tests/support/temp_dir.h"

namespace landsim {
namespace {

using testing::TempDir;

constexpr const char* kSensorSets =
    "--spp 2 --width 48 --set sensor.adc_bits=12 --set sensor.exposure_time=0.0004 "
    "--set render.reflectance=true";

// The default scene rendered with kSensorSets into dir/set.
testing::ProgramResult render_sensor_set(const TempDir& dir) {
  return testing::run_landsim(
      std::string("render ") + kSensorSets + " --out " + (dir / "set").string(), dir);
}

std::vector<std::uint16_t> digital_numbers(const std::filesystem::path& tif, int& channels) {
  auto in = OIIO::ImageInput::open(tif.string());
  EXPECT_TRUE(in) << tif;
  if (!in) return {};
  const OIIO::ImageSpec& spec = in->spec();
  channels = spec.nchannels;
  EXPECT_EQ(spec.format, OIIO::TypeDesc::UINT16);
  std::vector<std::uint16_t> dn(static_cast<std::size_t>(spec.width) * spec.height * channels);
  EXPECT_TRUE(in->read_image(0, 0, 0, channels, OIIO::TypeDesc::UINT16, dn.data()));
  return dn;
}

TEST(CliSense, RenderWritesDigitalNumbersAndSenseReproducesThem) {
  TempDir dir;
  const auto set = dir / "set";
  const auto r = render_sensor_set(dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto manifest = nlohmann::json::parse(testing::read_file(set / "manifest.json"));
  const auto& image = manifest["images"][0];
  const auto& sensor = image["sensor"];
  EXPECT_EQ(sensor["path"], "crater_dn.tif");
  EXPECT_DOUBLE_EQ(sensor["exposure_time_used_s"].get<double>(), 0.0004);
  ASSERT_EQ(sensor["channels"].size(), 3u);
  EXPECT_EQ(sensor["channels"][1]["layer"], "photons.G");
  EXPECT_GT(sensor["channels"][1]["mtf50_cycles_per_pixel"].get<double>(), 0.1);
  EXPECT_GT(image["irradiance"]["illuminance_lux"].get<double>(), 1000.0);
  EXPECT_TRUE(image["irradiance"]["layers"].contains("photons.R"));
  // The EXR holds the photon and reflectance layers and the sensor it was rendered with.
  Imf::InputFile exr((set / "crater.exr").c_str());
  for (const char* layer : {"photons.R", "reflectance.X", "reflectance.photons.B", "Y.variance"})
    EXPECT_NE(exr.header().channels().findChannel(layer), nullptr) << layer;
  EXPECT_NE(exr.header().findTypedAttribute<Imf::StringAttribute>("landsim/sensor"), nullptr);
  EXPECT_NE(exr.header().findTypedAttribute<Imf::StringAttribute>("landsim/irradiance"), nullptr);
  int channels = 0;
  const std::vector<std::uint16_t> rendered = digital_numbers(set / "crater_dn.tif", channels);
  EXPECT_EQ(channels, 3);
  std::uint16_t brightest = 0;
  for (const std::uint16_t v : rendered) brightest = std::max(brightest, v);
  EXPECT_GT(brightest, 100);
  EXPECT_LE(brightest, 4095);
  // The same sensor and seed: the same numbers, without tracing, in a new folder (SET_sensed)
  // beside the set, which stays as it was.
  const std::string manifest_text = testing::read_file(set / "manifest.json");
  ASSERT_EQ(testing::run_landsim("sense " + set.string() + "/", dir).exit_code, 0);
  const auto sensed = dir / "set_sensed";
  EXPECT_EQ(digital_numbers(sensed / "crater_dn.tif", channels), rendered);
  EXPECT_TRUE(std::filesystem::exists(sensed / "crater.exr"));
  EXPECT_TRUE(std::filesystem::exists(sensed / "manifest.json"));
  // Another noise seed: other numbers, the manifest says which seed.
  const auto again = testing::run_landsim(
      "sense " + set.string() + " --noise-seed 5 --out " + (dir / "seed5").string(), dir);
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_NE(digital_numbers(dir / "seed5" / "crater_dn.tif", channels), rendered);
  const auto after = nlohmann::json::parse(testing::read_file(dir / "seed5" / "manifest.json"));
  EXPECT_EQ(after["images"][0]["sensor"]["noise_seed"], 5);
  EXPECT_EQ(testing::read_file(set / "manifest.json"), manifest_text);
  EXPECT_EQ(digital_numbers(set / "crater_dn.tif", channels), rendered);
  // --in-place rewrites the set itself.
  ASSERT_EQ(
      testing::run_landsim("sense " + set.string() + " --noise-seed 5 --in-place", dir).exit_code,
      0);
  EXPECT_NE(digital_numbers(set / "crater_dn.tif", channels), rendered);
  EXPECT_EQ(nlohmann::json::parse(
                testing::read_file(set / "manifest.json"))["images"][0]["sensor"]["noise_seed"],
            5);
}

TEST(CliSense, RefusesChannelsNotRenderedAndSetsWithoutASensor) {
  TempDir dir;
  const auto set = dir / "set";
  ASSERT_EQ(render_sensor_set(dir).exit_code, 0);
  const auto xyz = dir.write("xyz.toml", "[sensor]\nchannels = \"xyz\"\n");
  const auto r = testing::run_landsim("sense " + set.string() + " --sensor " + xyz.string(), dir);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("channel X was not rendered (its channels: R, G, B)"), std::string::npos)
      << r.err;
  const auto bad = dir.write("bad.toml", "[sensor]\nread_noise = -1\n");
  const auto b = testing::run_landsim("sense " + set.string() + " --sensor " + bad.string(), dir);
  EXPECT_EQ(b.exit_code, 2);
  EXPECT_NE(b.err.find("bad.toml:2"), std::string::npos) << b.err;
  const auto plain = dir / "plain";
  ASSERT_EQ(
      testing::run_landsim("render --spp 1 --width 32 --out " + plain.string(), dir).exit_code, 0);
  const auto p = testing::run_landsim("sense " + plain.string(), dir);
  EXPECT_EQ(p.exit_code, 2);
  EXPECT_NE(p.err.find("rendered without [sensor]"), std::string::npos) << p.err;
  // Another sensor cannot stand in for photon layers the set never rendered.
  const auto q = testing::run_landsim("sense " + plain.string() + " --sensor " + xyz.string(), dir);
  EXPECT_EQ(q.exit_code, 2);
  EXPECT_NE(q.err.find("rendered without [sensor]"), std::string::npos) << q.err;
}

// A sensor behind a vignetting lens, applied by `sense` to a rendered set: each block of
// digital numbers falls by the fall-off written out here from the EXR's camera model (K), the
// natural cos^4 of the field angle times the lens's 1 + k1 r^2 (r = 1 at the corner).
TEST(CliSense, VignettingDarkensEachPixelByItsFieldAngle) {
  TempDir dir;
  const auto set = dir / "set";
  ASSERT_EQ(render_sensor_set(dir).exit_code, 0);
  const std::string model = "[sensor]\nadc_bits = 12\nexposure_time = 0.0004\nread_noise = 0\n";
  const auto plain = dir.write("plain.toml", model);
  const auto vignetting = dir.write(
      "vignetting.toml", model + "natural_vignetting = true\nlens_vignetting = [-0.2, 0, 0]\n");
  for (const char* name : {"plain", "vignetting"}) {
    const auto r =
        testing::run_landsim("sense " + set.string() + " --sensor " + (dir / name).string() +
                                 ".toml --out " + (dir / name).string(),
                             dir);
    ASSERT_EQ(r.exit_code, 0) << r.err;
  }
  int channels = 0;
  const std::vector<std::uint16_t> flat =
      digital_numbers(dir / "plain" / "crater_dn.tif", channels);
  const std::vector<std::uint16_t> dark =
      digital_numbers(dir / "vignetting" / "crater_dn.tif", channels);
  const auto manifest = nlohmann::json::parse(testing::read_file(set / "manifest.json"));
  const auto& camera = manifest["images"][0]["camera"];
  const int w = camera["width"], h = camera["height"];
  const double f = camera["K"][0][0], cx = camera["K"][0][2], cy = camera["K"][1][2];
  const double half_diagonal = 0.5 * std::hypot(w, h);
  ASSERT_EQ(flat.size(), static_cast<std::size_t>(w) * h * 3);
  // Blocks of 6 x 6 pixels: the corners, an edge and the centre.
  for (const auto& [x0, y0] :
       {std::pair{0, 0}, {w - 6, h - 6}, {0, h / 2 - 3}, {w / 2 - 3, h / 2 - 3}}) {
    double sum_flat = 0.0, sum_dark = 0.0, expected = 0.0;
    for (int y = y0; y < y0 + 6; ++y) {
      for (int x = x0; x < x0 + 6; ++x) {
        const double dx = x - cx, dy = y - cy;  // OpenCV's pixel centres
        const double cos_theta = f / std::sqrt(f * f + dx * dx + dy * dy);
        const double r2 = (dx * dx + dy * dy) / (half_diagonal * half_diagonal);
        const double fall_off = std::pow(cos_theta, 4) * (1.0 - 0.2 * r2);
        for (int c = 0; c < 3; ++c) {
          const std::size_t i = (static_cast<std::size_t>(y) * w + x) * 3 + c;
          sum_flat += flat[i];
          sum_dark += dark[i];
          expected += fall_off * flat[i];
        }
      }
    }
    ASSERT_GT(sum_flat, 36 * 3 * 50.0) << x0 << ", " << y0;
    EXPECT_NEAR(sum_dark / expected, 1.0, 0.02) << "block at " << x0 << ", " << y0;
  }
  const auto sensed =
      nlohmann::json::parse(testing::read_file(dir / "vignetting" / "manifest.json"));
  EXPECT_EQ(sensed["images"][0]["sensor"]["natural_vignetting"], true);
  EXPECT_EQ(sensed["images"][0]["sensor"]["lens_vignetting"][0], -0.2);
}

// The rays a render traced, from its --json report.
double rays_of(const testing::ProgramResult& r) {
  const auto image = nlohmann::json::parse(r.out)["images"][0];
  return image["seconds"].get<double>() * image["rays_per_second"].get<double>();
}

// A channel whose response has a faint near-infrared tail (1e-4 of its peak) traces the same
// paths as one without it: the path tracer's roulette ignores bins an output barely weighs.
TEST(CliSense, AFaintResponseTailCostsNoRays) {
  TempDir dir;
  dir.write("clean.csv", "nm,response\n500,0\n520,1\n600,1\n620,0\n");
  dir.write("tail.csv",
            "nm,response\n500,0\n520,1\n600,1\n620,0\n800,0\n820,0.0001\n900,0.0001\n920,0\n");
  const auto render = [&](const std::string& csv) {
    const std::string set =
        "'sensor.channels=[{name=\"g\", response=\"" + (dir / csv).string() + "\"}]'";
    return testing::run_landsim(
        "render --spp 2 --width 64 --json --set " + set + " --out " + (dir / csv).string() + ".set",
        dir);
  };
  const auto clean = render("clean.csv"), tail = render("tail.csv");
  ASSERT_EQ(clean.exit_code, 0) << clean.err;
  ASSERT_EQ(tail.exit_code, 0) << tail.err;
  EXPECT_NEAR(rays_of(tail) / rays_of(clean), 1.0, 1e-6);
}

TEST(CliCompare, StatisticalCallsAnotherSamplingSeedNoise) {
  TempDir dir;
  const auto a = dir / "a", b = dir / "b";
  ASSERT_EQ(testing::run_landsim("render --spp 4 --width 64 --out " + a.string(), dir).exit_code,
            0);
  ASSERT_EQ(testing::run_landsim(
                "render --spp 4 --width 64 --set render.sampling_seed=2 --out " + b.string(), dir)
                .exit_code,
            0);
  const auto r = testing::run_landsim(
      "compare " + a.string() + " " + b.string() + " --statistical --max-layer-diff 0", dir);
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("within the renders' noise"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace landsim
