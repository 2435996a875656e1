// End-to-end tests of the landsim program: exit codes, messages, files written or not.
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfStandardAttributes.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <regex>
#include <set>
#include <sstream>

#include "tests/support/run_program.h"
#include "tests/support/temp_dir.h"
#include "tests/support/tools.h"
#include "trees/species.h"

namespace landsim {
namespace {

using testing::TempDir;

using Result = testing::ProgramResult;

Result run(const std::string& args, const TempDir& dir) { return testing::run_landsim(args, dir); }

std::string volcano() { return testing::source_file("data/terrain/volcano.asc").string(); }

std::string scenario(const std::string& terrain_extra, const std::string& view_extra,
                     const std::string& render) {
  return "[terrain]\nelevation = \"" + volcano() + "\"\n" + terrain_extra +
         "\n[sun]\nelevation = 30\nazimuth = 300\n"
         "[[views]]\nname = \"v\"\nposition = [500.0, 900.0, 330.0]\ntarget = [280.0, 280.0, "
         "130.0]\n"
         "width = 32\nheight = 18\n" +
         view_extra + "\n[render]\n" + render + "\n";
}

// A [[species]] entry of the quaking aspen, with `extra` lines.
std::string aspen_entry(const std::string& extra) {
  return "\n[[species]]\nbit = 0\nfile = \"" +
         testing::source_file("data/species/quaking_aspen.toml").string() +
         "\"\nvariants = 1\ndensity_per_ha = 40\n" + extra + "\n";
}

// The volcano's land-cover classes and their class map as a [featuremaps] table (it
// selects species bits 0 and 1 and grass types 1 and 2).
std::string volcano_class_maps() {
  return "[featuremaps]\nclasses = \"" +
         testing::source_file("data/featuremaps/volcano_landcover.asc").string() +
         "\"\nclass_map = \"" +
         testing::source_file("scenes/examples/volcano_classes.toml").string() + "\"\n";
}

bool has_files(const std::filesystem::path& dir) {
  return std::filesystem::exists(dir) && !std::filesystem::is_empty(dir);
}

struct BadScenario {
  const char* name;
  std::string text;
  const char* key;  // what the message must name
};

// An [[objects]] entry of one of the example vehicles (data/objects/).
std::string object_entry(const std::string& name, const std::string& file, double x, double y) {
  return "[[objects]]\nname = \"" + name + "\"\nfile = \"" +
         testing::source_file("data/objects/" + file).string() + "\"\nposition = [" +
         std::to_string(x) + ", " + std::to_string(y) + "]\n";
}

// `landsim render` of a bad scenario: exit code 2, the scenario's file:line and the key in
// the message, nothing written.
Result render_refused(const BadScenario& c) {
  TempDir dir;
  const auto file = dir.write("bad.toml", c.text);
  const auto out = dir / "out";
  const Result r = run("render " + file.string() + " --out " + out.string(), dir);
  EXPECT_EQ(r.exit_code, 2) << c.name << ": " << r.err;
  EXPECT_NE(r.err.find(c.key), std::string::npos) << c.name << ": " << r.err;
  EXPECT_NE(r.err.find(file.string() + ":"), std::string::npos) << c.name << ": " << r.err;
  EXPECT_FALSE(has_files(out)) << c.name;
  return r;
}

TEST(Cli, BadScenariosExitTwoNameTheKeyAndWriteNothing) {
  const std::vector<BadScenario> cases = {
      {"unknown key", scenario("shade = 1", "", "spp = 2"), "unknown key 'shade'"},
      {"wrong type", scenario("", "fov = \"wide\"", "spp = 2"), "fov"},
      {"missing DEM",
       "[terrain]\nelevation = \"missing.asc\"\n" +
           scenario("", "", "").substr(scenario("", "", "").find("[sun]")),
       "elevation"},
      {"zero-sized image",
       scenario("", "", "spp = 2")
           .replace(scenario("", "", "spp = 2").find("width = 32"), 10, "width = 0"),
       "width"},
      {"negative spp", scenario("", "", "spp = -1"), "spp"},
      {"species growing nowhere", scenario("", "", "spp = 2") + aspen_entry(""),
       "[[species]] bit 0 grows nowhere"},
      {"cover fractions over 1",
       scenario("", "", "spp = 2") + aspen_entry("cover = 0.7") +
           aspen_entry("cover = 0.5").replace(aspen_entry("").find("bit = 0"), 7, "bit = 1"),
       "[species[1]] cover: the fractions"},
      {"unknown cover", scenario("", "", "spp = 2") + aspen_entry("cover = \"all\""),
       "[species[0]] cover: expected \"everywhere\""},
      {"unknown ground material in a rule",
       scenario("", "", "spp = 2") +
           "[[ground.rules]]\nmeasure = \"slope\"\nabove = 30\nbecomes = \"lava\"\n",
       "[ground.rules[0]] becomes: unknown ground material 'lava'"},
      {"a rule that changes nothing",
       scenario("", "", "spp = 2") + "[[ground.rules]]\nmeasure = \"height\"\nbelow = 10\n",
       "a rule must change something"},
      {"variation out of range", scenario("", "", "spp = 2") + "[ground]\nvariation = 1.5\n",
       "[ground] variation: expected from 0 to 1"},
      {"an object's file that is no mesh",
       scenario("", "", "spp = 2") + object_entry("a", "make_vehicles.py", 300.0, 400.0),
       "[objects[0]] file: cannot read mesh"},
      {"two objects of one name",
       scenario("", "", "spp = 2") + object_entry("a", "car.obj", 300.0, 400.0) +
           object_entry("a", "truck.obj", 320.0, 400.0),
       "[objects[1]] name: the name 'a' is used by another object"},
  };
  for (const BadScenario& c : cases) {
    const Result r = render_refused(c);
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1)
        << c.name << ": one message: " << r.err;
    EXPECT_TRUE(r.out.empty()) << c.name;
  }
}

// landsim brf measures a periodic cell, in directions above the horizon; it writes brf.json
// and brf.csv, every principal-plane direction a row.
TEST(Cli, BrfMeasuresAPeriodicCellAndRefusesWhatIsNot) {
  TempDir dir;
  const auto file = dir.write("plain.toml", scenario("", "", "spp = 1"));
  Result r = run("brf " + file.string(), dir);
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("set [terrain] periodic = true"), std::string::npos) << r.err;
  const std::string het01 = testing::source_file("scenes/rami/het01.toml").string();
  r = run("brf " + het01 + " --direction 95,0", dir);
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("--direction 95,0: expected zenith,azimuth"), std::string::npos) << r.err;
  const auto out = dir / "het01";
  r = run("brf " + het01 + " --spp 8 --budget-paths 0 --out " + out.string(), dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string csv = testing::read_file(out / "brf.csv");
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 77);  // a header and 76 directions
  EXPECT_EQ(csv.rfind("view_zenith_deg,zenith_deg,azimuth_deg,brf,brf_se", 0), 0u);
  EXPECT_NE(csv.find("\n-19,19,90,"), std::string::npos) << csv.substr(0, 300);
  EXPECT_TRUE(std::filesystem::exists(out / "brf.json"));
  EXPECT_TRUE(std::filesystem::exists(out / "brf.nc"));  // read by tests/python/test_brf_netcdf.py
}

// Monochromatic runs (docs/CANOPIES.md "Measures"): one factor per wavelength, the medium
// evaluated at each (661 and 679 nm share a bin, yet not their Rayleigh depth), the luminance
// none; a wavelength beyond the bins, or a budget asked of one, refused.
TEST(Cli, BrfMeasuresEachNamedWavelengthOnItsOwn) {
  TempDir dir;
  const std::string cell = testing::source_file("scenes/rami4atm/hom00_bla_sd2s_m03.toml").string();
  const auto out = dir / "mono";
  Result r =
      run("brf " + cell + " --spp 4096 --direction 0,0 --wavelength 661,679 --out " + out.string(),
          dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string csv = testing::read_file(out / "brf.csv");
  EXPECT_EQ(csv.rfind("view_zenith_deg,zenith_deg,azimuth_deg,brf,brf_se,radiance,radiance_se,"
                      "brf_661nm,brf_661nm_se,brf_679nm,brf_679nm_se,relative_azimuth_deg,paths\n",
                      0),
            0u)
      << csv;
  EXPECT_NE(csv.find("\n0,0,0,nan,nan,nan,nan,"), std::string::npos) << csv;  // no luminance
  const auto j = nlohmann::json::parse(testing::read_file(out / "brf.json"));
  EXPECT_EQ(j["wavelengths_nm"], nlohmann::json({661.0, 679.0}));
  const auto& bands = j["directions"][0]["bands"];
  EXPECT_TRUE(j["directions"][0]["brf"].is_null());
  const double short_brf = bands["661nm"]["brf"], long_brf = bands["679nm"]["brf"];
  const double se =
      std::hypot(bands["661nm"]["brf_se"].get<double>(), bands["679nm"]["brf_se"].get<double>());
  // Over black ground the air's light alone: Rayleigh's lambda^-4 makes 661 nm brighter by
  // several standard errors (the bins' means would make the two the same).
  EXPECT_GT(short_brf - long_brf, 5.0 * se) << short_brf << " " << long_brf;
  // --target-se bounds each wavelength's own factor (not the luminance, which it has none of).
  r = run("brf " + cell + " --spp 256 --direction 0,0 --wavelength 560 --target-se 0.002 --json",
          dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto aimed = nlohmann::json::parse(r.out)["directions"][0];
  const double brf = aimed["bands"]["560nm"]["brf"], brf_se = aimed["bands"]["560nm"]["brf_se"];
  EXPECT_LE(brf_se, 0.002 * brf);
  EXPECT_GT(aimed["paths"].get<int>(), 256);
  r = run("brf " + cell + " --wavelength 300", dir);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--wavelength 300: expected 380 to 1020 nm"), std::string::npos) << r.err;
  r = run("brf " + cell + " --wavelength 550 --budget-paths 1000", dir);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--budget-paths"), std::string::npos) << r.err;
}

// A periodic flat cell of Lambertian soil, albedo 0.3, under a sun 60 degrees up in the east
// and no sky, without [[views]]: its BRF is 0.3 in every direction.
std::filesystem::path lambertian_cell(const TempDir& dir) {
  return dir.write("cell.toml",
                   "[terrain]\nelevation = \"" +
                       testing::source_file("data/radiative_transfer/flat_cell.asc").string() +
                       "\"\nperiodic = true\nalbedo = [0.3, 0.3, 0.3]\n[ground]\n"
                       "soil_spectrum = \"flat\"\n[sun]\nelevation = 60\nazimuth = 90\n[sky]\n"
                       "model = \"none\"\n");
}

// Measures to a stated precision (issue 73 item 7): 0.5% by default, --spp alone exactly;
// RAMI's azimuth frame beside the compass's; the hemisphere grid DART and LESS write.
TEST(Cli, BrfMeasuresToAStatedPrecisionInEitherFrameAndOnAHemisphere) {
  TempDir dir;
  const auto cell = lambertian_cell(dir);
  // The grid: zenith 0, then 30 and 60 at azimuths 0, 90, 180, 270; a Lambertian soil's 0.3.
  Result r = run("brf " + cell.string() + " --hemisphere 30,90 --budget-paths 0 --json", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["directions"].size(), 9u);
  std::set<std::pair<double, double>> grid;
  for (const auto& d : j["directions"]) {
    grid.insert({d["zenith_deg"].get<double>(), d["azimuth_deg"].get<double>()});
    EXPECT_NEAR(d["brf"].get<double>(), 0.3, 0.01);
    EXPECT_FALSE(d.contains("view_zenith_deg"));  // not the principal plane
  }
  EXPECT_TRUE(grid.count({0.0, 0.0}) && grid.count({30.0, 270.0}) && grid.count({60.0, 180.0}));
  EXPECT_EQ(j["target_se"].get<double>(), 0.005);
  // RAMI's frame: the sun (azimuth 90, east) at 0, counter-clockwise seen from above: 90 in
  // it is north, the compass's 0.
  r = run("brf " + cell.string() +
              " --direction 30,0 --direction 30,90 --azimuth-frame rami --budget-paths 0 --json",
          dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["directions"][0]["azimuth_deg"].get<double>(), 90.0);
  EXPECT_EQ(j["directions"][0]["relative_azimuth_deg"].get<double>(), 0.0);
  EXPECT_EQ(j["directions"][1]["azimuth_deg"].get<double>(), 0.0);
  EXPECT_EQ(j["directions"][1]["relative_azimuth_deg"].get<double>(), 90.0);
  // A direction with noise (the air's light over a black soil): traced by default until its
  // error is 0.5% of it; --spp alone, exactly those paths.
  const std::string air = testing::source_file("scenes/rami4atm/hom00_bla_sd2s_m03.toml").string();
  r = run("brf " + air + " --direction 0,0 --wavelength 560 --json", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto aimed = nlohmann::json::parse(r.out)["directions"][0];
  const double brf = aimed["bands"]["560nm"]["brf"], se = aimed["bands"]["560nm"]["brf_se"];
  EXPECT_LE(se, 0.005 * std::max(brf, 0.01)) << brf;
  EXPECT_GT(aimed["paths"].get<int>(), 4096);  // 4,096 paths were not enough
  r = run("brf " + air + " --direction 0,0 --wavelength 560 --spp 256 --json", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out)["directions"][0]["paths"].get<int>(), 256);
  EXPECT_EQ(nlohmann::json::parse(r.out)["target_se"].get<double>(), 0.0);
  // Refused, by name: a grid of millions, a step of nothing, both a grid and directions.
  for (const std::string& bad : {"--hemisphere 0.1,0.1", "--hemisphere 0,30", "--hemisphere 10",
                                 "--hemisphere 10,30 --direction 0,0"}) {
    r = run("brf " + cell.string() + " " + bad, dir);
    EXPECT_EQ(r.exit_code, 2) << bad;
    EXPECT_NE(r.err.find("--hemisphere"), std::string::npos) << bad << ": " << r.err;
  }
}

// A periodic cell is measured without a camera (issue 71): brf takes it without [[views]];
// rendering it says what is missing.
TEST(Cli, APeriodicCellWithoutViewsIsMeasuredButNotRendered) {
  TempDir dir;
  const auto cell = lambertian_cell(dir);
  Result r = run("brf " + cell.string() + " --direction 0,0 --spp 64 --budget-paths 0 --json", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_NEAR(j["directions"][0]["brf"].get<double>(), 0.3, 0.01);  // a Lambertian soil's
  r = run("render " + cell.string() + " --out " + (dir / "out").string(), dir);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("at least one [[views]] table is required to render"), std::string::npos)
      << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "out" / "manifest.json"));
}

TEST(Cli, AGroundTextureThatCannotBeReadExitsTwoAtItsEntry) {
  TempDir dir;
  const auto junk = dir.write("rock.png", "not an image");
  const auto file =
      dir.write("texture.toml", scenario("", "", "spp = 1") + "[ground]\ntextures = { rock = \"" +
                                    junk.string() + "\" }\n");
  const auto out = dir / "out";
  const Result r = run("render " + file.string() + " --out " + out.string(), dir);
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find(file.string() + ":"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("[ground] textures"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(junk.string()), std::string::npos) << r.err;
  EXPECT_FALSE(has_files(out));
}

// A PNG whose header chunk fails its CRC: libpng's own handler printed "libpng error: IHDR:
// CRC error" (twice: header probe and read) before landsim's message, and the message called
// the ground's texture a bark texture. Now landsim's line is all the user reads.
TEST(Cli, ABrokenPngTextureIsOneLineOfLandsimsOwn) {
  TempDir dir;
  const std::string ihdr_bad_crc = std::string("\x89PNG\r\n\x1a\n", 8) +
                                   std::string("\0\0\0\x0dIHDR\0\0\0\x08\0\0\0\x08\x08\x02", 18) +
                                   std::string(7, '\0');
  const auto png = dir.write("soil.png", ihdr_bad_crc);
  const auto file =
      dir.write("texture.toml", scenario("", "", "spp = 1") + "[ground]\ntextures = { soil = \"" +
                                    png.string() + "\" }\n");
  const Result r = run("render " + file.string() + " --out " + (dir / "out").string(), dir);
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(r.err.find("libpng"), std::string::npos) << r.err;
  std::vector<std::string> said;  // every line but the progress's info lines
  std::istringstream err(r.err);
  for (std::string line; std::getline(err, line);)
    if (line.rfind("landsim: info: ", 0) != 0) said.push_back(line);
  ASSERT_EQ(said.size(), 1u) << r.err;
  EXPECT_EQ(said[0].rfind("landsim: error: ", 0), 0u) << r.err;
  EXPECT_NE(r.err.find("cannot read ground texture: PNG read error: IHDR: CRC error"),
            std::string::npos)
      << r.err;
}

TEST(Cli, BadContextRastersExitTwoAtTheirEntryAndWriteNothing) {
  TempDir dir;
  // An ESRI grid far from the volcano (which spans 0-610 m east, 0-870 m north).
  const auto far = dir.write("far.asc",
                             "ncols 2\nnrows 2\nxllcorner 50000\nyllcorner 50000\ncellsize "
                             "100\n1 2\n3 4\n");
  const auto junk = dir.write("junk.tif", "not a raster");
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"context = [\"" + far.string() + "\"]", "does not overlap the elevation grid"},
      {"context = [\"" + junk.string() + "\"]", "not a raster format GDAL can read"},
      {"context = [\"" + (dir / "missing.tif").string() + "\"]", "file not found"},
      // The grid stretched to 20 m cells would no longer lie on its context.
      {"context = [\"" + far.string() + "\"]\ncell_size = 20", "cell_size 20 differs"},
  };
  for (const auto& [context, expected] : cases) {
    const auto file = dir.write("context.toml", scenario(context, "", "spp = 1"));
    const auto out = dir / "out";
    const Result r = run("render " + file.string() + " --out " + out.string(), dir);
    EXPECT_EQ(r.exit_code, 2) << context << ": " << r.err;
    EXPECT_NE(r.err.find(file.string() + ":3:"), std::string::npos) << r.err;  // its line
    EXPECT_NE(r.err.find("context"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(expected), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_FALSE(has_files(out)) << context;
  }
}

TEST(Cli, CoverEverywherePlacesTreesAtTheDensityAskedWithoutRasters) {
  TempDir dir;
  const auto file = dir.write(
      "cover.toml", scenario("", "", "spp = 1") + aspen_entry("cover = \"everywhere\"") +
                        "[[grass]]\ntype = 1\ncover = { rectangle = [0.0, 0.0, 100.0, 100.0] }\n");
  const Result r = run("info " + file.string() + " --json", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto json = nlohmann::json::parse(r.out);
  // The volcano grid: 61 x 87 cells of 10 m, 53.07 ha; 40 trees per hectare.
  EXPECT_NEAR(json["instances"].get<double>(), 53.07 * 40.0, 0.01 * 53.07 * 40.0);
  // Grass on the 100 m square: 625 tiles of 4 m, the square resolved at the terrain's 10 m
  // cells (a cell's centre decides) and the tiles' centres.
  EXPECT_NEAR(json["grass_tiles"].get<double>(), 625.0, 0.15 * 625.0);
  const Result render = run("render " + file.string() + " --out " + (dir / "o").string(), dir);
  EXPECT_EQ(render.exit_code, 0) << render.err;
}

// Silent wrong scenes warn once, naming the file (and line), and --strict refuses them.
TEST(Cli, SilentWrongScenesWarnAndStrictRefusesThem) {
  TempDir dir;
  // The volcano's class map selects species bits 0 and 1 and grass types 1 and 2; only bit 0
  // and grass 1 are defined here.
  const std::string maps = volcano_class_maps();
  std::string text = scenario("", "", "spp = 1") + aspen_entry("") + "[[grass]]\ntype = 1\n";
  text.insert(text.find("[sun]"), maps);
  const auto file = dir.write("w.toml", text);
  const Result r = run("render " + file.string() + " --out " + (dir / "a").string(), dir);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("volcano_classes.toml: "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("select species bit 1, but no [[species]] has bit = 1"), std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("select grass type 2, but no [[grass]] has type = 2"), std::string::npos)
      << r.err;
  const Result strict =
      run("render " + file.string() + " --strict --out " + (dir / "b").string(), dir);
  EXPECT_EQ(strict.exit_code, 2);
  EXPECT_NE(strict.err.find("(refused: --strict)"), std::string::npos) << strict.err;
  EXPECT_FALSE(has_files(dir / "b"));

  // A camera 40 m under the ground.
  std::string under = scenario("", "", "spp = 1");
  under.replace(under.find("position = [500.0, 900.0, 330.0]"), 32,
                "position = [300.0, 400.0, 100.0]");
  const auto u = dir.write("u.toml", under);
  const Result below = run("info " + u.string(), dir);
  EXPECT_EQ(below.exit_code, 0);
  EXPECT_TRUE(std::regex_search(
      below.err,
      std::regex(
          R"(u\.toml:\d+:\d+: \[views "v"\] position: the camera is [0-9.]+ m below the ground)")))
      << below.err;
  EXPECT_EQ(run("info " + u.string() + " --strict", dir).exit_code, 2);

  // A camera 3 m up in a dense aspen wood on a flat grid: inside a tree's bounds.
  std::string flat = "ncols 20\nnrows 20\nxllcorner 0\nyllcorner 0\ncellsize 10\n";
  for (int i = 0; i < 20; ++i) flat += "0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0\n";
  dir.write("flat.asc", flat);
  const auto wood = dir.write(
      "wood.toml",
      "[terrain]\nelevation = \"flat.asc\"\n[sun]\nelevation = 40\nazimuth = 200\n"
      "[[views]]\nname = \"inside\"\nposition = [100.0, 100.0, 3.0]\ntarget = [150.0, 100.0, "
      "3.0]\nwidth = 16\nheight = 9\n" +
          aspen_entry("cover = \"everywhere\"\ndensity_per_ha = 1000")
              .replace(aspen_entry("").find("density_per_ha = 40"), 20, ""));
  const Result inside =
      run("export-obj " + wood.string() + " --max-trees 0 --out " + (dir / "w.obj").string(), dir);
  EXPECT_EQ(inside.exit_code, 0) << inside.err;
  EXPECT_NE(inside.err.find("[views \"inside\"] position: the camera is inside the bounds of a "
                            "tree"),
            std::string::npos)
      << inside.err;

  // An Arbaro file without Levels and 1DownAngle.
  std::string xml = testing::read_file(testing::source_file("data/species/quaking_aspen.xml"));
  for (const std::string name : {"Levels", "1DownAngle"}) {
    const std::size_t at = xml.find("<param name='" + name + "'");
    xml.erase(at, xml.find('\n', at) - at);
  }
  const auto species = dir.write("aspen.xml", xml);
  const Result tree = run("tree " + species.string() + " --json", dir);
  EXPECT_EQ(tree.exit_code, 0);
  EXPECT_NE(tree.err.find("aspen.xml: 2 parameters not given, Arbaro's defaults used: Levels, "
                          "1DownAngle"),
            std::string::npos)
      << tree.err;
  EXPECT_EQ(run("tree " + species.string() + " --strict", dir).exit_code, 2);
}

TEST(Cli, InitWritesAScenarioThatRendersWhereverItIs) {
  TempDir dir;
  const auto starter = dir / "my scene";
  const Result r = run("init \"" + starter.string() + "\"", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(std::filesystem::exists(starter / "scenario.toml"));
  // Moved elsewhere, it still renders (every path is relative to the scenario), without a
  // warning.
  const auto moved = dir / "elsewhere";
  std::filesystem::rename(starter, moved);
  const Result render = run("render " + (moved / "scenario.toml").string() +
                                " --strict --spp 1 --width 64 --out " + (dir / "out").string(),
                            dir);
  EXPECT_EQ(render.exit_code, 0) << render.err;
  EXPECT_TRUE(std::filesystem::exists(dir / "out" / "crater.exr"));
  const auto info =
      nlohmann::json::parse(run("info " + (moved / "scenario.toml").string() + " --json", dir).out);
  EXPECT_GT(info["instances"].get<double>(), 1000.0);  // its trees and grass are placed
  EXPECT_GT(info["grass_tiles"].get<double>(), 1000.0);
  // A folder that is not empty is refused, and left as it was.
  const Result again = run("init " + moved.string(), dir);
  EXPECT_EQ(again.exit_code, 2);
  EXPECT_NE(again.err.find("not an empty folder"), std::string::npos) << again.err;
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.path()),
                          std::filesystem::directory_iterator()),
            2);  // elsewhere and out: no partial folder left beside them
}

TEST(Cli, ExportObjWritesPrototypesOnceAndListsInstancesInTerrainCoordinates) {
  TempDir dir;
  const auto obj = dir / "scene.obj";
  const Result r = run("export-obj --out " + obj.string() + " --max-trees 20", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // It says what it wrote: size, prototypes, instances.
  const std::smatch m = [&] {
    std::smatch found;
    std::regex_search(
        r.out, found,
        std::regex(
            R"(ground \((\d+) triangles\), (\d+) tree prototypes once \((\d+) triangles\), 20 instances)"));
    return found;
  }();
  ASSERT_EQ(m.size(), 4u) << r.out;
  const double triangles = std::stod(m[1]) + std::stod(m[3]);
  // Each prototype once: the file grows with the unique triangles, not with the trees.
  EXPECT_LT(static_cast<double>(std::filesystem::file_size(obj)), 80.0 * triangles);
  std::istringstream csv(testing::read_file(dir / "scene.instances.csv"));
  std::string line;
  int rows = 0;
  while (std::getline(csv, line)) {
    if (line.empty() || line[0] == '#' || line.rfind("instance,", 0) == 0) continue;
    ++rows;
    double x = 0.0, y = 0.0;
    ASSERT_EQ(std::sscanf(line.c_str(), "%*d,%*d,%lf,%lf", &x, &y), 2) << line;
    // The volcano grid's own coordinates: 0-610 m east, 0-870 m north.
    EXPECT_TRUE(x >= 0.0 && x <= 610.0 && y >= 0.0 && y <= 870.0) << line;
  }
  EXPECT_EQ(rows, 20);
  // Flattened, the same 20 trees take far more.
  const Result flat =
      run("export-obj --out " + (dir / "flat.obj").string() + " --max-trees 20 --flatten", dir);
  ASSERT_EQ(flat.exit_code, 0) << flat.err;
  EXPECT_GT(std::filesystem::file_size(dir / "flat.obj"), 2 * std::filesystem::file_size(obj));
  EXPECT_FALSE(std::filesystem::exists(dir / "flat.instances.csv"));
}

TEST(Cli, BadCommandLineValuesExitTwo) {
  TempDir dir;
  EXPECT_EQ(run("render --spp -3", dir).exit_code, 2);
  // tree --wind takes [wind]'s range.
  const std::string aspen = testing::source_file("data/species/quaking_aspen.toml").string();
  EXPECT_EQ(run("tree " + aspen + " --wind 150", dir).exit_code, 2);
  EXPECT_EQ(run("tree " + aspen + " --wind 100 --json", dir).exit_code, 0);
  EXPECT_EQ(run("render --width 0", dir).exit_code, 2);
  EXPECT_EQ(run("render --no-such-flag", dir).exit_code, 2);
  const Result r = run("render --view nowhere --out " + (dir / "o").string(), dir);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("nowhere"), std::string::npos) << r.err;
  EXPECT_FALSE(has_files(dir / "o"));
}

TEST(Cli, DiscoverRendersAContactSheetAndWritesEachTilesSpecies) {
  TempDir dir;
  const auto sheet = dir / "sheet.png";
  const Result r = run("discover --count 4 --tile 32 --spp 1 --json --out " + sheet.string(), dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto json = nlohmann::json::parse(r.out);
  ASSERT_EQ(json["tiles"].size(), 4u);
  auto image = OIIO::ImageInput::open(sheet.string());
  ASSERT_TRUE(image);
  EXPECT_EQ(image->spec().width, 4 * 32);  // one row of four tiles
  EXPECT_EQ(image->spec().height, 32);
  std::set<double> heights;
  for (std::size_t k = 0; k < 4; ++k) {
    const auto& tile = json["tiles"][k];
    // Each tile's species file grows the same tree again with the tree command.
    const Result t = run("tree " + tile["species"].get<std::string>() + " --seed " +
                             std::to_string(k + 1) + " --json",
                         dir);
    ASSERT_EQ(t.exit_code, 0) << t.err;
    EXPECT_DOUBLE_EQ(nlohmann::json::parse(t.out)["height_m"].get<double>(),
                     tile["height_m"].get<double>());
    heights.insert(tile["height_m"].get<double>());
  }
  EXPECT_EQ(heights.size(), 4u);  // four different trees
  EXPECT_EQ(run("discover --count 0 --out " + (dir / "x.png").string(), dir).exit_code, 2);
  // A sheet too large to hold is refused before any work, nothing written.
  const Result huge =
      run("discover --count 400 --tile 2048 --out " + (dir / "h.png").string(), dir);
  EXPECT_EQ(huge.exit_code, 2);
  EXPECT_NE(huge.err.find("--count/--tile"), std::string::npos) << huge.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "h_species"));
}

TEST(Cli, GrowWritesAnImagePerAgeAndTheGrowthTable) {
  TempDir dir;
  const auto plane = testing::source_file("data/species/london_plane.toml").string();
  const auto out = dir / "growth";
  const Result r =
      run("grow " + plane + " --ages 10,30,90 --width 48 --height 48 --spp 1 --out " + out.string(),
          dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* f : {"age_010.png", "age_030.exr", "age_090.png", "growth.json", "growth.png"})
    EXPECT_TRUE(std::filesystem::exists(out / f)) << f;
  EXPECT_NE(r.err.find("outside the growth data"), std::string::npos) << "age 90 is clamped";
  const auto table = nlohmann::json::parse(testing::read_file(out / "growth.json"));
  ASSERT_EQ(table["ages"].size(), 3u);
  EXPECT_LT(table["ages"][2]["age_used"].get<double>(), 90.0);
  // The model follows this tree's own sizes (the equations plus its scatter), which differ
  // from the equations' mean tree.
  double off_mean = 0.0;
  for (const auto& row : table["ages"])
    for (const char* k : {"height_m", "crown_diameter_m", "crown_height_m", "dbh_cm"}) {
      const double model = row["model"][k], own = row["individual"][k];
      EXPECT_NEAR(model, own, 0.1 * own) << k << " at " << row["age"];
      off_mean = std::max(off_mean, std::abs(own / row["equations"][k].get<double>() - 1.0));
    }
  EXPECT_GT(off_mean, 0.02);
}

// The internodes of a self-organising tree, listed so that a pruning can name one: pruning a
// listed branch makes a tree with fewer stems; another core has none (exit 2, no file).
TEST(Cli, TreeListsInternodesAPruningCanName) {
  TempDir dir;
  const std::string upright =
      testing::read_file(testing::source_file("data/species/so_upright.toml"));
  const auto species = dir.write("so.toml", upright);
  const Result r =
      run("tree " + species.string() + " --json --internodes " + (dir / "in.csv").string(), dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const int stems = nlohmann::json::parse(r.out)["stems"]["total"];
  std::istringstream csv(testing::read_file(dir / "in.csv"));
  std::string line;
  std::getline(csv, line);
  EXPECT_EQ(line.rfind("internode,parent,step,", 0), 0u) << line;
  // The first branch that started by step 4 and is alive at the end.
  std::string chosen;
  int rows = 0;
  while (std::getline(csv, line)) {
    ++rows;
    std::vector<std::string> c;
    std::stringstream ss(line);
    for (std::string cell; std::getline(ss, cell, ',');) c.push_back(cell);
    // The cut names the branch by a point: the middle of its first internode.
    if (chosen.empty() && c[7] == "1" && c[5] == "1" && std::stoi(c[2]) <= 4)
      for (int k = 0; k < 3; ++k)
        chosen +=
            (k ? ", " : "") + std::to_string(0.5 * (std::stod(c[8 + k]) + std::stod(c[11 + k])));
  }
  EXPECT_GT(rows, stems);  // an internode per row, several per stem
  ASSERT_FALSE(chosen.empty());
  const auto pruned =
      dir.write("pruned.toml", upright + "\n[[prune]]\nstep = 5\nat = [" + chosen + "]\n");
  const Result after = run("tree " + pruned.string() + " --json", dir);
  ASSERT_EQ(after.exit_code, 0) << after.err;
  EXPECT_LT(nlohmann::json::parse(after.out)["stems"]["total"].get<int>(), stems);
  const Result other =
      run("tree " + testing::source_file("data/species/quaking_aspen.toml").string() +
              " --internodes " + (dir / "x.csv").string(),
          dir);
  EXPECT_EQ(other.exit_code, 2);
  EXPECT_NE(other.err.find("only self-organising"), std::string::npos) << other.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "x.csv"));
}

// Every core grows: a Weber & Penn tree through the default ages (a fifth to all of its
// mature age) gets taller and gains stems; the age is written in each picture.
TEST(Cli, GrowTakesEveryCore) {
  TempDir dir;
  const auto aspen = testing::source_file("data/species/quaking_aspen.toml").string();
  const auto out = dir / "aspen";
  const Result r =
      run("grow " + aspen + " --width 64 --height 64 --spp 1 --json --out " + out.string(), dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto table = nlohmann::json::parse(r.out);
  EXPECT_EQ(table["core"], "weber_penn");
  const auto& ages = table["ages"];
  ASSERT_EQ(ages.size(), 5u);
  EXPECT_DOUBLE_EQ(ages[4]["age_used"].get<double>(), 30.0);  // the default mature age
  for (std::size_t i = 1; i < ages.size(); ++i) {
    EXPECT_GT(ages[i]["model"]["height_m"].get<double>(),
              ages[i - 1]["model"]["height_m"].get<double>());
    EXPECT_GE(ages[i]["stems"].get<int>(), ages[i - 1]["stems"].get<int>());
  }
  EXPECT_LT(ages[0]["stems"].get<int>(), ages[4]["stems"].get<int>());
  EXPECT_FALSE(ages[0].contains("equations"));
  // The label: the two pictures' top-left corners differ where "6 years" and "30 years" are.
  auto first = OIIO::ImageInput::open((out / "age_006.png").string());
  auto last = OIIO::ImageInput::open((out / "age_030.png").string());
  ASSERT_TRUE(first && last);
  std::vector<unsigned char> a(64 * 64 * 3), b(a.size());
  ASSERT_TRUE(first->read_image(0, 0, 0, 3, OIIO::TypeDesc::UINT8, a.data()));
  ASSERT_TRUE(last->read_image(0, 0, 0, 3, OIIO::TypeDesc::UINT8, b.data()));
  int differ = 0;
  for (int y = 4; y < 20; ++y)
    for (int x = 0; x < 64; ++x) differ += a[3 * (y * 64 + x)] != b[3 * (y * 64 + x)];
  EXPECT_GT(differ, 5);
}

// A cutaway shows the root system below the cut: in the picture's lower half (below the
// ground, seen edge-on) a rooted species draws its roots; a rootless one leaves it empty.
TEST(Cli, GrowCutawayShowsTheRootsBelowTheGround) {
  TempDir dir;
  const auto below_ground = [&](const std::string& species) {
    const auto out = dir / species;
    const auto file = testing::source_file("data/species/" + species + ".toml").string();
    const Result r =
        run("grow " + file + " --ages 30 --cutaway --width 96 --height 96 --spp 1 --out " +
                out.string(),
            dir);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    auto png = OIIO::ImageInput::open((out / "age_030.png").string());
    std::vector<unsigned char> p(96 * 96 * 3);
    if (!png || !png->read_image(0, 0, 0, 3, OIIO::TypeDesc::UINT8, p.data())) return -1;
    const auto at = [&](int x, int y, int c) { return static_cast<int>(p[3 * (y * 96 + x) + c]); };
    const auto differ = [&](int x, int y, int x0, int y0) {
      int d = 0;
      for (int c = 0; c < 3; ++c) d += std::abs(at(x, y, c) - at(x0, y0, c));
      return d;
    };
    // The cut is the first row whose left edge is not sky (the sky is bluer than red, the
    // empty space under the ground is not); two rows below it on, count pixels unlike their
    // row's first (that space darkens row by row).
    int cut = 0;
    while (cut < 95 && at(0, cut, 0) < at(0, cut, 2)) ++cut;
    int marked = 0;
    for (int y = cut + 2; y < 96; ++y) {
      for (int x = 0; x < 96; ++x) marked += differ(x, y, 0, y) > 30;
    }
    return marked;
  };
  EXPECT_GT(below_ground("graph_rooted"), 10);
  EXPECT_EQ(below_ground("graph_round_crown"), 0);
}

TEST(Cli, RendersAScenarioToExrAndPngWithJson) {
  TempDir dir;
  const auto file = dir.write("ok.toml", scenario("", "", "spp = 2"));
  const auto out = dir / "out";
  const Result r =
      run("render " + file.string() + " --out " + out.string() + " --json --threads 2", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto json = nlohmann::json::parse(r.out);
  ASSERT_EQ(json["images"].size(), 1u);
  const auto& image = json["images"][0];
  EXPECT_EQ(image["view"], "v");
  EXPECT_EQ(image["path"], (out / "v.exr").string());
  EXPECT_EQ(image["frame"], 0.0);
  EXPECT_GT(image["seconds"].get<double>(), 0.0);
  EXPECT_GT(image["rays_per_second"].get<double>(), 0.0);
  EXPECT_TRUE(std::filesystem::exists(out / "v.png"));
  Imf::InputFile exr((out / "v.exr").c_str());
  EXPECT_EQ(exr.header().dataWindow().max.x, 31);
  EXPECT_EQ(exr.header().dataWindow().max.y, 17);
  // The two images and the manifest, no temporary files left.
  EXPECT_EQ(testing::file_names(out), (std::set<std::string>{"v.exr", "v.png", "manifest.json"}));
  const auto manifest = nlohmann::json::parse(testing::read_file(out / "manifest.json"));
  ASSERT_EQ(manifest["images"].size(), 1u);
  EXPECT_EQ(manifest["images"][0]["path"], "v.exr");
  EXPECT_EQ(manifest["images"][0]["camera"]["width"], 32);
  EXPECT_EQ(manifest["images"][0]["camera"]["position"][0], 500.0);
  EXPECT_NE(r.err.find("100%"), std::string::npos) << "progress goes to stderr";
}

// Objects are placed when the scene is built, after the memory estimate's report: their
// errors are the one error message of the run.
TEST(Cli, BadObjectsExitTwoAtTheirEntryAndWriteNothing) {
  const std::vector<BadScenario> cases = {
      {"an object off the terrain",
       scenario("", "", "spp = 2") + object_entry("a", "car.obj", -5000.0, 400.0),
       "[objects[0]] position: the object at (-5000, 400) stands partly outside the terrain"},
  };
  for (const BadScenario& c : cases) {
    const Result r = render_refused(c);
    std::size_t errors = 0;
    for (std::size_t at = r.err.find("error:"); at != std::string::npos;
         at = r.err.find("error:", at + 1))
      ++errors;
    EXPECT_EQ(errors, 1u) << c.name << ": " << r.err;
  }
}

// The EXR's UINT channel `name`, row by row.
std::vector<std::uint32_t> uint_channel(const std::filesystem::path& exr, const char* name) {
  Imf::InputFile in(exr.c_str());
  const Imath::Box2i dw = in.header().dataWindow();
  const int w = dw.max.x - dw.min.x + 1, h = dw.max.y - dw.min.y + 1;
  std::vector<std::uint32_t> out(static_cast<std::size_t>(w) * h);
  Imf::FrameBuffer fb;
  fb.insert(name, Imf::Slice(Imf::UINT, reinterpret_cast<char*>(out.data()), sizeof(std::uint32_t),
                             sizeof(std::uint32_t) * static_cast<std::size_t>(w)));
  in.setFrameBuffer(fb);
  in.readPixels(dw.min.y, dw.max.y);
  return out;
}

TEST(Cli, TheTargetLayerAndTheManifestAgreeOnEveryObject) {
  TempDir dir;
  // Two vehicles on the volcano, scaled up to be seen from 500 m and more.
  std::string text = scenario("", "", "spp = 2");
  text.replace(text.find("width = 32\nheight = 18"), 22, "width = 160\nheight = 90\nfov = 6");
  text += object_entry("car", "car.obj", 360.0, 450.0) + "heading = 30\nscale = 4\n" +
          object_entry("truck", "truck.obj", 330.0, 385.0) + "scale = 3\n";
  const auto file = dir.write("s.toml", text);
  const auto out = dir / "out";
  const Result r = run("render " + file.string() + " --out " + out.string(), dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::vector<std::uint32_t> target = uint_channel(out / "v.exr", "target");
  const std::vector<std::uint32_t> object = uint_channel(out / "v.exr", "object");
  const auto manifest = nlohmann::json::parse(testing::read_file(out / "manifest.json"));
  const auto& objects = manifest["images"][0]["objects"];
  ASSERT_EQ(objects.size(), 2u);
  for (std::uint32_t id = 1; id <= 2; ++id) {
    const auto& o = objects[id - 1];
    EXPECT_EQ(o["target"], id);
    std::uint64_t pixels = 0;
    int x0 = 1 << 30, y0 = 1 << 30, x1 = -1, y1 = -1;
    std::uint64_t first_on_it = 0;
    for (std::size_t i = 0; i < target.size(); ++i) {
      // A pixel whose first sample is on an object has it as its target (the target layer
      // counts every sample, the object layer the first: edges differ).
      EXPECT_TRUE(object[i] != 5u || target[i] != 0u) << "class 5 without a target";
      if (target[i] != id) continue;
      ++pixels;
      first_on_it += object[i] == 5u;
      const int x = static_cast<int>(i % 160), y = static_cast<int>(i / 160);
      x0 = std::min(x0, x);
      y0 = std::min(y0, y);
      x1 = std::max(x1, x);
      y1 = std::max(y1, y);
    }
    ASSERT_GT(pixels, 20u) << o["name"];
    EXPECT_GT(first_on_it, pixels / 2) << o["name"];
    EXPECT_EQ(o["visible_pixels"], pixels) << o["name"];
    EXPECT_EQ(o["bbox"]["x0"], x0);
    EXPECT_EQ(o["bbox"]["y0"], y0);
    EXPECT_EQ(o["bbox"]["x1"], x1);
    EXPECT_EQ(o["bbox"]["y1"], y1);
    EXPECT_GE(o["footprint_pixels"].get<std::uint64_t>(), pixels);
    EXPECT_GT(o["range_m"].get<double>(), 100.0);
  }
  EXPECT_EQ(objects[0]["name"], "car");
  // --resume keeps the truth of finished images.
  const Result again = run("render " + file.string() + " --out " + out.string() + " --resume", dir);
  ASSERT_EQ(again.exit_code, 0) << again.err;
  const auto resumed = nlohmann::json::parse(testing::read_file(out / "manifest.json"));
  EXPECT_EQ(resumed["images"][0]["objects"], objects);
}

TEST(Cli, CompareExitsZeroForEqualSetsThreeForChangedOnesTwoForNoSet) {
  TempDir dir;
  const auto a = dir / "a", b = dir / "b";
  ASSERT_EQ(run("render --out " + a.string() + " --width 48 --spp 2", dir).exit_code, 0);
  std::filesystem::copy(a, b, std::filesystem::copy_options::recursive);
  const Result same = run("compare " + a.string() + " " + b.string(), dir);
  EXPECT_EQ(same.exit_code, 0) << same.err;
  EXPECT_NE(same.out.find("pass: 1 images compared"), std::string::npos) << same.out;
  // Twice the samples: the same scene with less noise.
  ASSERT_EQ(run("render --out " + b.string() + " --width 48 --spp 4", dir).exit_code, 0);
  const Result changed = run(
      "compare " + b.string() + " " + a.string() + " --json --out " + (dir / "r").string(), dir);
  EXPECT_EQ(changed.exit_code, 3) << changed.err;
  EXPECT_FALSE(nlohmann::json::parse(changed.out)["pass"].get<bool>());
  EXPECT_TRUE(std::filesystem::exists(dir / "r" / "report.html"));
  const Result none = run("compare " + (dir / "nothing").string() + " " + a.string(), dir);
  EXPECT_EQ(none.exit_code, 2);
  EXPECT_NE(none.err.find("manifest.json"), std::string::npos) << none.err;
}

TEST(Cli, DefaultSceneWithSizeOverridesKeepsTheAspect) {
  TempDir dir;
  const auto out = dir / "out";
  const Result r = run("render --out " + out.string() + " --width 64 --spp 1 --json", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  Imf::InputFile exr((out / "crater.exr").c_str());
  EXPECT_EQ(exr.header().dataWindow().max.x, 63);
  EXPECT_EQ(exr.header().dataWindow().max.y, 35);  // 640 x 360 -> 64 x 36
}

TEST(Cli, HelpAndVersion) {
  TempDir dir;
  const Result help = run("--help", dir);
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_NE(help.out.find("render"), std::string::npos);
  const Result version = run("--version", dir);
  EXPECT_EQ(version.exit_code, 0);
  EXPECT_NE(version.out.find("landsim "), std::string::npos);
  const Result none = run("", dir);
  EXPECT_EQ(none.exit_code, 2);
}

TEST(Cli, ImageSetsNameEveryFrameAndListThemInTheManifest) {
  TempDir dir;
  // Two frames in wind: trees sway, so the two images differ.
  const std::string scen =
      scenario("", "", "spp = 1\nframes = [0.0, 3.0]") + "[wind]\nspeed = 12.0\ngust = 6.0\n";
  std::string text = scen;
  text.insert(text.find("[sun]"),
              "[featuremaps]\nclasses = \"" +
                  testing::source_file("data/featuremaps/volcano_landcover.asc").string() +
                  "\"\nclass_map = \"" +
                  testing::source_file("scenes/examples/volcano_classes.toml").string() +
                  "\"\n[[species]]\nbit = 0\nfile = \"" +
                  testing::source_file("data/species/quaking_aspen.toml").string() +
                  "\"\nvariants = 1\ndensity_per_ha = 400\n");
  text.replace(text.find("position = [500.0, 900.0, 330.0]"), 32,
               "position = [300.0, 40.0, 150.0]");
  text.replace(text.find("target = [280.0, 280.0, 130.0]"), 30, "target = [300.0, 120.0, 110.0]");
  const auto file = dir.write("set.toml", text);
  const auto out = dir / "out";
  const Result r = run("render " + file.string() + " --out " + out.string() + " --json", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto json = nlohmann::json::parse(r.out);
  ASSERT_EQ(json["images"].size(), 2u);
  EXPECT_EQ(json["images"][1]["frame"], 3.0);
  // Named as the manifest names them.
  EXPECT_EQ(json["images"][1]["frame_index"], 1);
  EXPECT_EQ(json["images"][1]["time_s"], 3.0);
  EXPECT_TRUE(std::filesystem::exists(out / "v_f0000.exr"));
  EXPECT_TRUE(std::filesystem::exists(out / "v_f0001.png"));
  const auto manifest = nlohmann::json::parse(testing::read_file(out / "manifest.json"));
  ASSERT_EQ(manifest["images"].size(), 2u);
  EXPECT_EQ(manifest["images"][1]["path"], "v_f0001.exr");
  EXPECT_EQ(manifest["images"][1]["time_s"], 3.0);
  EXPECT_EQ(manifest["wind"]["speed"], 12.0);
  EXPECT_NE(testing::read_file(out / "v_f0000.exr"), testing::read_file(out / "v_f0001.exr"));
}

TEST(Cli, RenderedExrHoldsEveryLayerAndTheDocumentedMetadata) {
  // docs/SCENARIO.md "Image sets" and docs/ATMOSPHERE.md: the layers, the string metadata,
  // and OpenEXR's camera matrices, which put the camera at the camera frame's origin and
  // its target straight ahead, at the image's centre.
  TempDir dir;
  std::string text = scenario("", "", "spp = 1\nseed = 7");
  text += "\n[atmosphere]\n[atmosphere.aerosol]\nvisibility = 9000.0\n";
  const auto file = dir.write("meta.toml", text);
  const auto out = dir / "out";
  const Result r = run("render " + file.string() + " --out " + out.string(), dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  Imf::InputFile in((out / "v.exr").c_str());
  const Imf::Header& h = in.header();
  for (const char* name : {"R", "G", "B", "Y", "Z", "N.X", "N.Y", "N.Z", "albedo.R", "albedo.G",
                           "albedo.B", "object", "species", "instance", "lod", "target"})
    EXPECT_NE(h.channels().findChannel(name), nullptr) << name;
  const auto meta = [&](const std::string& key) {
    const auto* a = h.findTypedAttribute<Imf::StringAttribute>("landsim/" + key);
    return a != nullptr ? a->value() : std::string("(missing)");
  };
  EXPECT_EQ(meta("sun_elevation_deg"), "30");
  EXPECT_EQ(meta("sun_azimuth_deg"), "300");
  EXPECT_EQ(meta("sky"), "atmosphere");
  EXPECT_EQ(meta("haze"),
            "atmosphere: U.S. Standard, Rayleigh, ozone, aerosol visibility 9000 m, scale height "
            "1200 m");
  EXPECT_EQ(meta("spp"), "1");
  EXPECT_EQ(meta("seed"), "7");
  EXPECT_EQ(meta("view"), "v");
  // The scenario's hash: 16 hex digits of the scenario as read, comments and spacing aside
  // (the same file with a comment and blank lines renders with the same hash), a value not.
  EXPECT_TRUE(std::regex_match(meta("scenario_hash"), std::regex("[0-9a-f]{16}")))
      << meta("scenario_hash");
  const auto hash_of = [&](const std::string& name, const std::string& variant) {
    const auto set = dir / name;
    const Result again = run("render " + dir.write(name + ".toml", variant).string() +
                                 " --width 8 --height 8 --out " + set.string(),
                             dir);
    EXPECT_EQ(again.exit_code, 0) << again.err;
    const Imf::InputFile other((set / "v.exr").c_str());
    const auto* a =
        other.header().findTypedAttribute<Imf::StringAttribute>("landsim/scenario_hash");
    return a != nullptr ? a->value() : std::string("(missing)");
  };
  EXPECT_EQ(hash_of("commented", "# the same scenario\n\n" + text + "\n\n"), meta("scenario_hash"));
  std::string hazier = text;
  hazier.replace(hazier.find("visibility = 9000.0"), 19, "visibility = 8000.0");
  EXPECT_NE(hash_of("hazier", hazier), meta("scenario_hash"));
  // Positions in the EXR's matrices are relative to the scene origin (the grid's centre).
  double ox = 0, oy = 0, oz = 0;
  std::istringstream(meta("scene_origin")) >> ox >> oy >> oz;
  EXPECT_DOUBLE_EQ(ox, 305.0);  // 61 cells of 10 m
  EXPECT_DOUBLE_EQ(oy, 435.0);  // 87 cells
  ASSERT_TRUE(Imf::hasWorldToCamera(h));
  ASSERT_TRUE(Imf::hasWorldToNDC(h));
  const Imath::V3f eye(float(500.0 - ox), float(900.0 - oy), float(330.0 - oz));
  const Imath::V3f target(float(280.0 - ox), float(280.0 - oy), float(130.0 - oz));
  Imath::V3f in_camera;
  Imf::worldToCamera(h).multVecMatrix(eye, in_camera);
  EXPECT_NEAR(in_camera.length(), 0.0f, 0.01f);
  Imf::worldToCamera(h).multVecMatrix(target, in_camera);
  EXPECT_NEAR(in_camera.x, 0.0f, 0.01f);
  EXPECT_NEAR(in_camera.y, 0.0f, 0.01f);
  EXPECT_NEAR(-in_camera.z, (target - eye).length(), 0.01f);
  Imath::V3f ndc;
  Imf::worldToNDC(h).multVecMatrix(target, ndc);
  EXPECT_NEAR(ndc.x, 0.0f, 1e-4f);
  EXPECT_NEAR(ndc.y, 0.0f, 1e-4f);
  // A point 50 m above the target is higher in the image (NDC y up).
  Imf::worldToNDC(h).multVecMatrix(target + Imath::V3f(0, 0, 50), ndc);
  EXPECT_GT(ndc.y, 0.1f);
  // Points 12 degrees right of the line of sight and 8 degrees above it land where a 40-degree
  // vertical field of view over 32 x 18 pixels puts them: NDC x = tan 12 / (tan 20 x 32/18),
  // y = tan 8 / tan 20; pixel column (x + 1) / 2 x 32 = 21.3, row (1 - y) / 2 x 18 = 5.5.
  const Imath::V3f forward = (target - eye).normalized();
  const Imath::V3f right = forward.cross(Imath::V3f(0, 0, 1)).normalized();
  const Imath::V3f up = right.cross(forward);
  const float range = (target - eye).length();
  const double tan_half = std::tan(20.0 * std::numbers::pi / 180.0);
  Imf::worldToNDC(h).multVecMatrix(
      eye + range * forward + range * std::tan(12.0f * std::numbers::pi_v<float> / 180.0f) * right,
      ndc);
  const double want_x = std::tan(12.0 * std::numbers::pi / 180.0) / (tan_half * 32.0 / 18.0);
  EXPECT_NEAR(ndc.x, want_x, 1e-4);
  EXPECT_NEAR(ndc.y, 0.0, 1e-4);
  EXPECT_EQ(static_cast<int>((ndc.x + 1.0) / 2.0 * 32.0), 21);
  Imf::worldToNDC(h).multVecMatrix(
      eye + range * forward + range * std::tan(8.0f * std::numbers::pi_v<float> / 180.0f) * up,
      ndc);
  EXPECT_NEAR(ndc.x, 0.0, 1e-4);
  EXPECT_NEAR(ndc.y, std::tan(8.0 * std::numbers::pi / 180.0) / tan_half, 1e-4);
  EXPECT_EQ(static_cast<int>((1.0 - ndc.y) / 2.0 * 18.0), 5);
}

TEST(Cli, TaskIndexRendersOneImageAndCheckFindsTheMissingOnes) {
  // docs/CLUSTER.md, without MPI: image N of the set, frame-major (N = frame x views + view);
  // --check renders nothing, lists what is missing (exit 1), then writes the manifest (exit 0).
  TempDir dir;
  std::string text = scenario("", "", "spp = 1\nframes = [0.0, 2.0]");
  text +=
      "\n[[views]]\nname = \"w\"\nposition = [100.0, 100.0, 400.0]\n"
      "target = [300.0, 400.0, 150.0]\nwidth = 16\nheight = 12\n";
  const auto file = dir.write("set.toml", text);
  const auto out = dir / "out";
  const auto render = [&](const std::string& extra) {
    return run("render " + file.string() + " --out " + out.string() + " " + extra, dir);
  };
  ASSERT_EQ(render("--task-index 3").exit_code, 0);  // frame 1, view w
  EXPECT_TRUE(std::filesystem::exists(out / "w_f0001.exr"));
  EXPECT_FALSE(std::filesystem::exists(out / "v_f0000.exr"));
  EXPECT_FALSE(std::filesystem::exists(out / "v_f0001.exr"));
  const Result missing = render("--check");
  EXPECT_EQ(missing.exit_code, 1);
  EXPECT_NE(missing.err.find("v_f0000.exr"), std::string::npos) << missing.err;
  EXPECT_NE(missing.err.find("w_f0000.exr"), std::string::npos) << missing.err;
  EXPECT_EQ(missing.err.find("w_f0001.exr"), std::string::npos) << missing.err;
  EXPECT_NE(render("--task-index 4").exit_code, 0);  // the set has 4 images: 0-3
  for (int i : {0, 1, 2}) ASSERT_EQ(render("--task-index " + std::to_string(i)).exit_code, 0);
  const Result done = render("--check");
  EXPECT_EQ(done.exit_code, 0) << done.err;
  const auto manifest = nlohmann::json::parse(testing::read_file(out / "manifest.json"));
  EXPECT_EQ(manifest["images"].size(), 4u);
}

TEST(Cli, KagweneExampleRendersOneViewFromAnotherFolder) {
  // README: render scenes/examples/kagwene.toml --view highlands: the real sanctuary, its
  // paths resolved against the scenario wherever landsim runs; only the named view is drawn.
  TempDir dir;
  const auto out = dir / "kagwene";
  const Result r = run("render " + testing::source_file("scenes/examples/kagwene.toml").string() +
                           " --view highlands --width 48 --spp 1 --json --out " + out.string(),
                       dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto json = nlohmann::json::parse(r.out);
  ASSERT_EQ(json["images"].size(), 1u);
  EXPECT_EQ(json["images"][0]["view"], "highlands");
  EXPECT_TRUE(std::filesystem::exists(out / "highlands.exr"));
  EXPECT_FALSE(std::filesystem::exists(out / "north_rim.exr"));
  const auto manifest = nlohmann::json::parse(testing::read_file(out / "manifest.json"));
  ASSERT_EQ(manifest["images"].size(), 1u);
  EXPECT_EQ(manifest["images"][0]["camera"]["width"], 48);
  // The sanctuary's trees are drawn: some pixels are leaves (object 3).
  Imf::InputFile in((out / "highlands.exr").c_str());
  const Imath::Box2i w = in.header().dataWindow();
  const int width = w.max.x - w.min.x + 1, height = w.max.y - w.min.y + 1;
  std::vector<std::uint32_t> object(static_cast<std::size_t>(width * height));
  Imf::FrameBuffer fb;
  fb.insert("object", Imf::Slice(Imf::UINT, reinterpret_cast<char*>(object.data()),
                                 sizeof(std::uint32_t), sizeof(std::uint32_t) * width));
  in.setFrameBuffer(fb);
  in.readPixels(w.min.y, w.max.y);
  EXPECT_GT(std::count(object.begin(), object.end(), 3u), 0);
  EXPECT_GT(std::count(object.begin(), object.end(), 1u), 0);  // and the ground
}

TEST(Cli, RenderWritesBandLayersAndListsTheBands) {
  TempDir dir;
  dir.write("nir.csv", "nm,response\n770,0\n770,1\n900,1\n900,0\n");
  std::string text = scenario("", "", "spp = 2");  // 32 x 18
  text +=
      "[[bands]]\nname = \"red\"\ncentre = 660\nwidth = 60\n"
      "[[bands]]\nname = \"nir\"\nresponse = \"nir.csv\"\n";
  const auto file = dir.write("bands.toml", text);
  const auto out = dir / "out";
  const Result r = run("render " + file.string() + " --out " + out.string(), dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto manifest = nlohmann::json::parse(testing::read_file(out / "manifest.json"));
  ASSERT_EQ(manifest["bands"].size(), 2u);
  EXPECT_EQ(manifest["bands"][0]["layer"], "band.red");
  EXPECT_EQ(manifest["bands"][0]["definition"], "box 630-690 nm");
  EXPECT_EQ(manifest["bands"][1]["unit"], "W m-2 sr-1");
  const std::string exr = (out / (manifest["images"][0]["path"].get<std::string>())).string();
  Imf::InputFile in(exr.c_str());
  ASSERT_NE(in.header().channels().findChannel("band.red"), nullptr);
  ASSERT_NE(in.header().channels().findChannel("band.nir"), nullptr);
  const auto* definition = in.header().findTypedAttribute<Imf::StringAttribute>("landsim/band.red");
  ASSERT_NE(definition, nullptr);
  EXPECT_EQ(definition->value(), "box 630-690 nm");
  const auto* unit = in.header().findTypedAttribute<Imf::StringAttribute>("landsim/band_unit");
  ASSERT_NE(unit, nullptr);
  EXPECT_EQ(unit->value(), "W m-2 sr-1");
  std::vector<float> red(32 * 18), nir(32 * 18);
  Imf::FrameBuffer fb;
  fb.insert("band.red", Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(red.data()), sizeof(float),
                                   sizeof(float) * 32));
  fb.insert("band.nir", Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(nir.data()), sizeof(float),
                                   sizeof(float) * 32));
  in.setFrameBuffer(fb);
  in.readPixels(0, 17);
  double red_sum = 0.0, nir_sum = 0.0;
  for (std::size_t i = 0; i < red.size(); ++i) {
    red_sum += red[i];
    nir_sum += nir[i];
  }
  EXPECT_GT(red_sum, 0.0);
  EXPECT_GT(nir_sum, red_sum);  // 130 nm of near infrared against 60 nm of red, bare ground
}

// A 320 x 180 render of 32 spp (seconds long) writing checkpoints every `checkpoint`
// seconds, and a child process running it into `out` with two threads.
std::filesystem::path long_render(const TempDir& dir, const std::string& checkpoint) {
  std::string text =
      scenario("", "width = 320\nheight = 180", "spp = 32\ncheckpoint_seconds = " + checkpoint);
  text.replace(text.find("width = 32\nheight = 18\n"), 22, "");
  return dir.write("long.toml", text);
}

// Waits (up to five minutes: CI machines under a parallel suite are slow) until `path`
// exists; false if it never came or the child `pid` ended first.
bool wait_for(const std::filesystem::path& path, pid_t pid) {
  for (int i = 0; i < 300000; ++i) {
    if (std::filesystem::exists(path)) return true;
    int status = 0;
    if (::waitpid(pid, &status, WNOHANG) == pid) return false;
    ::usleep(1000);
  }
  ::kill(pid, SIGKILL);
  int status = 0;
  ::waitpid(pid, &status, 0);
  return false;
}

pid_t start_render(const std::filesystem::path& file, const std::filesystem::path& out) {
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::execl(LANDSIM_BINARY, LANDSIM_BINARY, "render", file.c_str(), "--out", out.c_str(),
            "--threads", "2", nullptr);
    ::_exit(127);
  }
  return pid;
}

TEST(Cli, KilledRenderResumesToTheSameImage) {
  TempDir dir;
  const auto file = long_render(dir, "0.0001");
  const auto whole = dir / "whole";
  ASSERT_EQ(
      run("render " + file.string() + " --out " + whole.string() + " --threads 2", dir).exit_code,
      0);
  // Start the same render, kill it once its first checkpoint exists, then resume it.
  const auto out = dir / "resumed";
  std::filesystem::create_directories(out);
  const pid_t pid = start_render(file, out);
  const auto checkpoint = out / "v.checkpoint.exr";
  ASSERT_TRUE(wait_for(checkpoint, pid)) << "no checkpoint appeared while rendering";
  ::kill(pid, SIGKILL);
  int status = 0;
  ::waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFSIGNALED(status)) << "the render finished before it could be killed";
  EXPECT_FALSE(std::filesystem::exists(out / "v.exr"));  // nothing half-written
  const Result r =
      run("render " + file.string() + " --out " + out.string() + " --threads 1 --resume", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("resuming"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(checkpoint));
  EXPECT_EQ(testing::read_file(out / "v.exr"), testing::read_file(whole / "v.exr"));
}

// A self-organising species with a bend and its edits named by points renders as a stand of
// four variants (issue 41: so_bent's bend named internode numbers and grew for seed 1 only).
TEST(Cli, ASpeciesWithEditsRendersAsSeveralVariants) {
  TempDir dir;
  const std::string maps = volcano_class_maps();
  std::string text = scenario("", "", "spp = 1") + "\n[[species]]\nbit = 0\nfile = \"" +
                     testing::source_file("data/species/so_bent.toml").string() +
                     "\"\nvariants = 4\ndensity_per_ha = 5\n";
  text.insert(text.find("[sun]"), maps);
  const auto file = dir.write("bent.toml", text);
  const Result r = run("render " + file.string() + " --out " + (dir / "out").string(), dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("of 4 variants"), std::string::npos) << r.err;
  EXPECT_TRUE(std::filesystem::exists(dir / "out" / "v.exr"));
}

// --set sets any scenario key for one run, with the file's validation: a set sun changes the
// image, a bad value exits 2 naming the override and writes nothing.
TEST(Cli, SetOverridesAScenarioKeyWithItsValidation) {
  TempDir dir;
  const auto file = dir.write("s.toml", scenario("", "", "spp = 1"));
  ASSERT_EQ(run("render " + file.string() + " --out " + (dir / "a").string(), dir).exit_code, 0);
  const Result low = run("render " + file.string() + " --out " + (dir / "b").string() +
                             " --set sun.elevation=5 --set render.seed=3",
                         dir);
  ASSERT_EQ(low.exit_code, 0) << low.err;
  EXPECT_NE(testing::read_file(dir / "a" / "v.exr"), testing::read_file(dir / "b" / "v.exr"));
  const Result bad =
      run("render " + file.string() + " --out " + (dir / "c").string() + " --set sun.elevation=95",
          dir);
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("--set sun.elevation=95: [sun] elevation"), std::string::npos) << bad.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "c"));
  const Result info = run("info " + file.string() + " --json --set views.0.width=64", dir);
  ASSERT_EQ(info.exit_code, 0) << info.err;
}

// --resume renders only what is missing: finished images of the same scenario, view, time,
// samples, seed and size are kept as they are; another sample count renders them again.
TEST(Cli, ResumeSkipsFinishedImages) {
  TempDir dir;
  const auto file = dir.write("set.toml", scenario("", "", "spp = 1\nframes = [0.0, 1.0]"));
  const auto out = dir / "out";
  ASSERT_EQ(run("render " + file.string() + " --out " + out.string(), dir).exit_code, 0);
  const std::string first = testing::read_file(out / "v_f0000.exr");
  std::filesystem::remove(out / "v_f0001.exr");
  const Result resumed =
      run("render " + file.string() + " --out " + out.string() + " --resume", dir);
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  EXPECT_NE(resumed.err.find("skipped 1 finished images"), std::string::npos) << resumed.err;
  EXPECT_TRUE(std::filesystem::exists(out / "v_f0001.exr"));
  EXPECT_EQ(testing::read_file(out / "v_f0000.exr"), first);
  EXPECT_TRUE(std::filesystem::exists(out / "manifest.json"));
  EXPECT_EQ(nlohmann::json::parse(testing::read_file(out / "manifest.json"))["images"].size(), 2u);
  const Result other =
      run("render " + file.string() + " --out " + out.string() + " --resume --spp 2", dir);
  ASSERT_EQ(other.exit_code, 0) << other.err;
  EXPECT_EQ(other.err.find("skipped"), std::string::npos) << other.err;
  EXPECT_NE(testing::read_file(out / "v_f0000.exr"), first);
}

// SIGTERM (a batch system's time limit) stops a render at its next wave of tiles with a
// checkpoint written and exit code 143; --resume finishes it to the uninterrupted image.
TEST(Cli, TerminatedRenderWritesItsCheckpointAndResumes) {
  TempDir dir;
  const auto file = long_render(dir, "1e6");
  const auto out = dir / "out";
  const pid_t pid = start_render(file, out);
  // The output directory appears when tracing starts; then ask the render to stop.
  ASSERT_TRUE(wait_for(out, pid)) << "the render ended before tracing began";
  ::usleep(100000);
  ::kill(pid, SIGTERM);
  int status = 0;
  ::waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFEXITED(status)) << "landsim died of the signal instead of stopping";
  ASSERT_EQ(WEXITSTATUS(status), 128 + SIGTERM) << "the render finished before the signal";
  EXPECT_TRUE(std::filesystem::exists(out / "v.checkpoint.exr"));
  EXPECT_FALSE(std::filesystem::exists(out / "v.exr"));
  const Result resumed =
      run("render " + file.string() + " --out " + out.string() + " --threads 2 --resume", dir);
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  EXPECT_NE(resumed.err.find("resuming"), std::string::npos) << resumed.err;
  const auto whole = dir / "whole";
  ASSERT_EQ(
      run("render " + file.string() + " --out " + whole.string() + " --threads 2", dir).exit_code,
      0);
  EXPECT_EQ(testing::read_file(out / "v.exr"), testing::read_file(whole / "v.exr"));
}

TEST(Cli, CrosscheckReportsTheContractAndFailsPastThresholds) {
  LANDSIM_REQUIRE_TOOL("povray", "povray");
  TempDir dir;
  std::string classes =
      "ncols 61\nnrows 87\nxllcorner 0.0\nyllcorner 0.0\ncellsize 10.0\nNODATA_value -9999\n";
  for (int r = 0; r < 87; ++r) {
    for (int c = 0; c < 61; ++c) classes += (r >= 5 && r < 11 && c >= 20 && c < 26) ? "1 " : "0 ";
    classes += "\n";
  }
  dir.write("cls.asc", classes);
  dir.write("map.toml", "[[class]]\nvalue = 1\nspecies = [{ bit = 0, fraction = 1.0 }]\n");
  const auto file =
      dir.write("small.toml",
                "[terrain]\nelevation = \"" + volcano() +
                    "\"\n[featuremaps]\nclasses = \"cls.asc\"\n"
                    "class_map = \"map.toml\"\n[[species]]\nbit = 0\nfile = \"" +
                    testing::source_file("data/species/fanpalm.xml").string() +
                    "\"\nvariants = 1\ndensity_per_ha = 12\n[sun]\nelevation = 35\nazimuth = 250\n"
                    "[[views]]\nname = \"s\"\nposition = [230.0, 700.0, 126.0]\ntarget = [230.0, "
                    "790.0, 104.0]\n"
                    "width = 64\nheight = 40\n");
  const Result ok = run(
      "crosscheck " + file.string() + " --out " + (dir / "a").string() + " --spp 1 --json", dir);
  ASSERT_EQ(ok.exit_code, 0) << ok.err;
  const auto j = nlohmann::json::parse(ok.out);
  for (const char* key : {"object_iou", "luminance_mean_rel_diff", "luminance_region_max_rel_diff",
                          "landsim_seconds", "povray_seconds", "pass"}) {
    EXPECT_TRUE(j.contains(key)) << key;
  }
  EXPECT_EQ(j["pass"], true);
  // Progress of both renderers on stderr.
  EXPECT_NE(ok.err.find("crosscheck: landsim 100%"), std::string::npos) << ok.err;
  EXPECT_NE(ok.err.find("crosscheck: POV-Ray 100%"), std::string::npos) << ok.err;
  EXPECT_NE(ok.err.find("crosscheck: POV-Ray done"), std::string::npos) << ok.err;
  // --width alone keeps the view's aspect (64 x 40 -> 32 x 20); the side-by-side holds the
  // three panels and, under them, the legend with the heat map's colour bar.
  const Result small =
      run("crosscheck " + file.string() + " --out " + (dir / "w").string() + " --spp 1 --width 32",
          dir);
  ASSERT_EQ(small.exit_code, 0) << small.err;
  auto sheet = OIIO::ImageInput::open((dir / "w" / "side_by_side.png").string());
  ASSERT_TRUE(sheet);
  EXPECT_EQ(sheet->spec().width, 3 * 32);
  EXPECT_GT(sheet->spec().height, 20);
  const Result strict = run("crosscheck " + file.string() + " --out " + (dir / "b").string() +
                                " --spp 1 --max-mean-diff 0",
                            dir);
  EXPECT_EQ(strict.exit_code, 3) << strict.err;
  EXPECT_NE(strict.out.find("FAIL"), std::string::npos);
  const Result pov = run("export-pov " + file.string() + " --out " + (dir / "pov").string(), dir);
  EXPECT_EQ(pov.exit_code, 0) << pov.err;
  EXPECT_TRUE(std::filesystem::exists(dir / "pov" / "scene.pov"));
  // The ground's shading variation reaches POV-Ray as vertex colours: a palette of them.
  const std::string meshes = testing::read_file(dir / "pov" / "meshes.inc");
  const std::size_t list = meshes.find("texture_list { ");
  ASSERT_NE(list, std::string::npos);
  EXPECT_GT(std::stoi(meshes.substr(list + 15, 8)), 20);
  EXPECT_EQ(
      run("export-pov " + file.string() + " --out " + (dir / "p2").string() + " --frame 5", dir)
          .exit_code,
      2);
  // The export as a user's own scene: compared at its camera; a camera landsim cannot match
  // and --pov with --reference are refused (exit 2), nothing written.
  const std::string scene_pov = (dir / "pov" / "scene.pov").string();
  const Result own = run("crosscheck " + file.string() + " --out " + (dir / "own").string() +
                             " --spp 1 --json --pov " + scene_pov,
                         dir);
  ASSERT_EQ(own.exit_code, 0) << own.err;
  EXPECT_EQ(nlohmann::json::parse(own.out)["pass"], true) << own.out;
  dir.write("turned.pov", "// a user's scene\ncamera {\n  location <1, 2, 3>\n  rotate y*30\n}\n");
  const Result turned = run("crosscheck " + file.string() + " --out " + (dir / "t").string() +
                                " --pov " + (dir / "turned.pov").string(),
                            dir);
  EXPECT_EQ(turned.exit_code, 2);
  EXPECT_NE(turned.err.find("turned.pov:4: camera: rotate"), std::string::npos) << turned.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "t" / "report.json"));
  const Result both = run("crosscheck " + file.string() + " --out " + (dir / "u").string() +
                              " --pov " + scene_pov + " --reference " + scene_pov,
                          dir);
  EXPECT_EQ(both.exit_code, 2) << both.err;
  EXPECT_NE(both.err.find("excludes"), std::string::npos) << both.err;
}

// The reference of `crosscheck --reference` is checked from its header before anything
// renders: garbage, an image of the wrong size, and a PNG whose header claims 100000 x 100000
// pixels (before: 120 GB asked for, after landsim.exr was written) are refused with exit 2,
// nothing written.
TEST(Cli, ACrosscheckReferenceIsCheckedBeforeAnythingRenders) {
  TempDir dir;
  const auto s = dir.write("s.toml", scenario("", "", "spp = 1"));
  // A PNG signature, an IHDR chunk of 100000 x 100000 RGB, an IDAT of two bytes, IEND
  // (every CRC right): a header that opens, and no pixels.
  const std::string huge(
      "\x89\x50\x4e\x47\x0d\x0a\x1a\x0a\x00\x00\x00\x0d\x49\x48\x44\x52\x00\x01"
      "\x86\xa0\x00\x01\x86\xa0\x08\x02\x00\x00\x00\x27\x30\x9c\x9f"
      "\x00\x00\x00\x02\x49\x44\x41\x54\x78\x9c\x62\xa4\x91\x2b"
      "\x00\x00\x00\x00\x49\x45\x4e\x44\xae\x42\x60\x82",
      59);
  std::vector<float> one{0.5f, 0.5f, 0.5f};
  struct Case {
    std::string file, content, message;
  };
  for (const Case& c : {Case{"garbage.png", "not an image at all\n", "cannot read the reference"},
                        Case{"huge.png", huge, "100000 x 100000"},
                        Case{"small.exr", "",
                             "the reference is 1 x 1 pixels, the view renders "
                             "32 x 18"}}) {
    std::filesystem::path ref;
    if (c.content.empty()) {
      ref = dir / c.file;
      auto exr = OIIO::ImageOutput::create(ref.string());
      ASSERT_TRUE(exr && exr->open(ref.string(), OIIO::ImageSpec(1, 1, 3, OIIO::TypeDesc::FLOAT)));
      ASSERT_TRUE(exr->write_image(OIIO::TypeDesc::FLOAT, one.data()));
      exr->close();
    } else {
      ref = dir.write(c.file, c.content);
    }
    const auto out = dir / ("check_" + c.file);
    const Result r =
        run("crosscheck " + s.string() + " --out " + out.string() + " --reference " + ref.string(),
            dir);
    EXPECT_EQ(r.exit_code, 2) << c.file << ": " << r.err;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << c.file << ": " << r.err;
    EXPECT_FALSE(std::filesystem::exists(out)) << c.file;
  }
}

// A user's POV-Ray scene that POV-Ray refuses (it includes itself; it includes a file that is
// not POV-Ray's): POV-Ray's own words at its file and line, exit 2, nothing left (before: exit
// 1, "internal error: POV-Ray failed: see .../povray.log", and the files written so far).
TEST(Cli, APovSceneThatPovRayRefusesIsSaidWithItsFileAndLine) {
  LANDSIM_REQUIRE_TOOL("povray", "povray");
  TempDir dir;
  const auto s = dir.write("s.toml", scenario("", "", "spp = 1"));
  const std::string camera =
      "camera { location <0, 1, -3> right x*image_width/image_height look_at <0, 0, 0> }\n";
  dir.write("self.pov", camera + "#include \"self.pov\"\n");
  dir.write("notes.txt", "root:x:0:0\n");
  dir.write("other.pov", camera + "\n#include \"notes.txt\"\n");
  for (const auto& [scene, said] :
       {std::pair{"self.pov", "self.pov:2: POV-Ray: Too many nested include files"},
        std::pair{"other.pov", "notes.txt:1: POV-Ray: Expected 'object or directive'"}}) {
    const auto out = dir / (std::string("check_") + scene);
    const Result r = run(
        "crosscheck " + s.string() + " --out " + out.string() + " --pov " + (dir / scene).string(),
        dir);
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find(said), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("internal error"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(out)) << scene;
  }
}

TEST(Cli, InfoDescribesTheDefaultScene) {
  TempDir dir;
  const Result r = run("info --json", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  const auto per_species = j["instances_per_species"];
  ASSERT_EQ(per_species.size(), 2u);
  EXPECT_EQ(j["instances"].get<long>(),
            per_species["quaking_aspen"].get<long>() + per_species["ca_black_oak"].get<long>());
  EXPECT_GT(j["instances"].get<long>(), 500);
  EXPECT_LE(j["unique_variants"].get<long>(), 7);  // 4 aspen + 3 oak variants at most
  EXPECT_GT(j["triangles_instanced"].get<long>(), 100 * j["triangles_stored"].get<long>());
  EXPECT_GT(j["memory_estimate_bytes"].get<long>(), 0);
}

TEST(Cli, InfoGivesTheRendersOwnMemoryEstimate) {
  // Both count the modules a render loads (the image module before its estimate), so the
  // estimate `info` prints is the one `render` checks against its budget.
  TempDir dir;
  const Result info = run("info --json", dir);
  const Result render = run("render --spp 1 --json --out " + (dir / "r").string(), dir);
  ASSERT_EQ(info.exit_code, 0) << info.err;
  ASSERT_EQ(render.exit_code, 0) << render.err;
  const auto a = nlohmann::json::parse(info.out)["memory_estimate_bytes"].get<double>();
  const auto b = nlohmann::json::parse(render.out)["memory_estimate_bytes"].get<double>();
  EXPECT_NEAR(a / b, 1.0, 0.05) << a << " against " << b;
}

// The Kagwene example with every species at 99000 trees per hectare (inside the documented
// ranges): about ninety million trees, which no machine here could hold.
std::string huge_kagwene(const TempDir& dir) {
  std::string text = testing::read_file(testing::source_file("scenes/examples/kagwene.toml"));
  text = std::regex_replace(text, std::regex("density_per_ha = \\d+"), "density_per_ha = 99000");
  text = std::regex_replace(text, std::regex("min_spacing = [0-9.]+"), "min_spacing = 0.0");
  text = std::regex_replace(text, std::regex("\"\\.\\./\\.\\./"),
                            "\"" + testing::source_file(".").string() + "/");
  text = std::regex_replace(
      text, std::regex("\"kagwene_classes"),
      "\"" + testing::source_file("scenes/examples").string() + "/kagwene_classes");
  return dir.write("huge.toml", text).string();
}

// Misspelt commands, tables, keys and species parameters get the name that was probably
// meant; a name close to nothing gets no guess.
TEST(Cli, MisspeltNamesSuggestTheClosest) {
  TempDir dir;
  const Result command = run("rendr", dir);
  EXPECT_EQ(command.exit_code, 2);
  EXPECT_NE(command.err.find("unknown command 'rendr' (did you mean 'render'?)"), std::string::npos)
      << command.err;
  const auto table = dir.write("t.toml", scenario("", "", "spp = 1") + "[hazee]\n");
  const Result t = run("info " + table.string(), dir);
  EXPECT_EQ(t.exit_code, 2);
  EXPECT_NE(t.err.find("'hazee' (did you mean 'haze'?)"), std::string::npos) << t.err;
  const auto key = dir.write("k.toml", scenario("", "", "spp = 1\nsede = 3"));
  const Result k = run("info " + key.string(), dir);
  EXPECT_EQ(k.exit_code, 2);
  EXPECT_NE(k.err.find("[render] unknown key 'sede' (did you mean 'seed'?)"), std::string::npos)
      << k.err;
  const auto far = dir.write("f.toml", scenario("", "", "spp = 1\nqwxzv = 3"));
  const Result f = run("info " + far.string(), dir);
  EXPECT_EQ(f.err.find("did you mean"), std::string::npos) << f.err;
  const auto species = dir.write("s.toml", "core = \"weber_penn\"\nLeafScal = 0.2\n");
  const Result sp = run("tree " + species.string(), dir);
  EXPECT_EQ(sp.exit_code, 2);
  EXPECT_NE(sp.err.find("'LeafScal' (did you mean 'LeafScale'?)"), std::string::npos) << sp.err;
}

// Every command that renders takes --spp in the scenario's range, 16 by default.
TEST(Cli, SppIsTheSameOptionEverywhere) {
  TempDir dir;
  for (const std::string command : {"render", "crosscheck", "discover", "grow", "plate"}) {
    const Result help = run(command + " --help", dir);
    EXPECT_NE(help.out.find("in [1 - 1048576]"), std::string::npos) << command << help.out;
    if (command != "render") {  // render's default is the scenario's
      EXPECT_NE(help.out.find("[1 - 1048576]=16"), std::string::npos) << command << help.out;
    }
  }
}

// Scenario errors found after reading still point at the file and line.
TEST(Cli, LateScenarioErrorsNameTheLine) {
  TempDir dir;
  const std::string species = "\n[[species]]\nbit = 0\nfile = \"" +
                              testing::source_file("data/species/quaking_aspen.toml").string() +
                              "\"\n";
  const auto no_map = dir.write("n.toml", scenario("", "", "spp = 1") + species);
  const Result n = run("info " + no_map.string(), dir);
  EXPECT_EQ(n.exit_code, 2);
  EXPECT_TRUE(std::regex_search(
      n.err, std::regex(R"(n\.toml:\d+:\d+: \[\[species\]\] bit 0 grows nowhere)")))
      << n.err;
  const auto spaced = dir.write(
      "s.toml", scenario("", "", "spp = 1") + species +
                    "density_per_ha = 10000\nmin_spacing = 2.0\n[featuremaps]\nclasses = \"" +
                    testing::source_file("data/featuremaps/volcano_landcover.asc").string() +
                    "\"\nclass_map = \"" +
                    testing::source_file("scenes/examples/volcano_classes.toml").string() + "\"\n");
  const Result sp = run("info " + spaced.string(), dir);
  EXPECT_EQ(sp.exit_code, 2);
  EXPECT_TRUE(std::regex_search(
      sp.err,
      std::regex(
          R"(s\.toml:\d+:\d+: \[species\[0\]\] min_spacing: expected at most the grid spacing 1 m)")))
      << sp.err;
}

// A species file given where a scenario belongs, and the reverse, is named for what it is;
// a view's errors name the view.
TEST(Cli, FileKindsAndViewsAreNamedInMessages) {
  TempDir dir;
  const Result species_as_scenario =
      run("info " + testing::source_file("data/species/quaking_aspen.toml").string(), dir);
  EXPECT_EQ(species_as_scenario.exit_code, 2);
  EXPECT_NE(species_as_scenario.err.find("this is a species file"), std::string::npos)
      << species_as_scenario.err;
  const Result scenario_as_species =
      run("tree " + testing::source_file("scenes/examples/default.toml").string(), dir);
  EXPECT_EQ(scenario_as_species.exit_code, 2);
  EXPECT_NE(scenario_as_species.err.find("this is a scenario, not a species file"),
            std::string::npos)
      << scenario_as_species.err;
  const auto view = dir.write("v.toml", scenario("", "fov = 190.0", "spp = 1"));
  const Result v = run("info " + view.string(), dir);
  EXPECT_EQ(v.exit_code, 2);
  EXPECT_NE(v.err.find("[views \"v\"] fov: expected"), std::string::npos) << v.err;
}

TEST(Cli, InfoEstimatesAHugeSceneWithoutBuildingIt) {
  TempDir dir;
  const Result r = run("info --json " + huge_kagwene(dir), dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_GT(j["instances"].get<double>(), 5e7);
  EXPECT_GT(j["memory_estimate_bytes"].get<double>(), 1e10);
  EXPECT_GT(j["memory_parts_bytes"].size(), 3u);
}

TEST(Cli, RenderRefusesASceneOverItsMemoryBudgetBeforeBuildingIt) {
#ifdef LANDSIM_SANITIZED
  GTEST_SKIP() << "AddressSanitizer reserves terabytes of address space for its shadow "
                  "memory, so no address-space limit (ulimit -v) can hold it; the normal "
                  "build runs this test";
#endif
  TempDir dir;
  const auto out = dir / "out";
  // The default budget, under a 16 GB address-space limit whatever the machine has.
  const Result huge =
      testing::run_command("ulimit -v 16000000; exec " + std::string(LANDSIM_BINARY) + " render " +
                               huge_kagwene(dir) + " --out " + out.string(),
                           dir);
  EXPECT_EQ(huge.exit_code, 2) << huge.err;
  EXPECT_NE(huge.err.find("80% of the address-space limit"), std::string::npos) << huge.err;
  EXPECT_NE(huge.err.find("tree instances"), std::string::npos) << huge.err;
  EXPECT_NE(huge.err.find("density_per_ha"), std::string::npos) << huge.err;
  EXPECT_EQ(huge.err.find("scene built"), std::string::npos) << huge.err;
  EXPECT_FALSE(std::filesystem::exists(out));
  const Result small = run("render --max-memory 100MB --out " + out.string(), dir);
  EXPECT_EQ(small.exit_code, 2) << small.err;
  EXPECT_NE(small.err.find("--max-memory allows 100 MB"), std::string::npos) << small.err;
  EXPECT_NE(small.err.find("tree variants"), std::string::npos) << small.err;
  EXPECT_FALSE(std::filesystem::exists(out));
  const auto file = dir.write("s.toml", scenario("", "", "max_memory = \"1 MB\""));
  const Result scenario_budget = run("render " + file.string() + " --out " + out.string(), dir);
  EXPECT_EQ(scenario_budget.exit_code, 2) << scenario_budget.err;
  EXPECT_NE(scenario_budget.err.find("[render] max_memory allows 1 MB"), std::string::npos)
      << scenario_budget.err;
  EXPECT_FALSE(std::filesystem::exists(out));
  EXPECT_EQ(run("render --max-memory lots --out " + out.string(), dir).exit_code, 2);
}

// Under an address-space limit the default scene passes a generous --max-memory, then runs
// out of memory while it is built or handed to Embree: a clean exit 1 with a message, no
// signal, no output. 750 MB leaves the program room to load (about 400 MB of libraries)
// but not to render (about 1 GB of address space).
TEST(Cli, RenderOutOfMemoryUnderAnAddressSpaceLimitFailsCleanly) {
#ifdef LANDSIM_SANITIZED
  GTEST_SKIP() << "AddressSanitizer reserves terabytes of address space for its shadow "
                  "memory, so no address-space limit (ulimit -v) can hold it; the normal "
                  "build runs this test";
#endif
  TempDir dir;
  const auto out = dir / "out";
  const Result r = testing::run_command(
      "ulimit -v 750000; exec " + std::string(LANDSIM_BINARY) +
          " render --max-memory 100GB --spp 1 --threads 2 --out " + out.string(),
      dir);
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find("error: "), std::string::npos) << r.err;
  EXPECT_FALSE(has_files(out)) << r.err;
}

TEST(Cli, FeaturemapBuildWritesA16BitMap) {
  TempDir dir;
  const auto out = dir / "veg.tif";
  const Result r = run(
      "featuremap build " + testing::source_file("data/terrain/gorillas_vegetation.asc").string() +
          " --map " + testing::source_file("scenes/examples/kagwene_classes.toml").string() +
          " --out " + out.string(),
      dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(std::filesystem::exists(out));
  const Result bad = run(
      "featuremap build " + testing::source_file("data/terrain/gorillas_vegetation.asc").string() +
          " --map " + dir.write("bad.toml", "[[class]]\nvalue = 1\ngrass = 9\n").string() +
          " --out " + (dir / "bad.tif").string(),
      dir);
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("grass"), std::string::npos) << bad.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "bad.tif"));
}

// An output name taken by a directory: the machine's refusal, said as such (not an internal
// error), exit 1, and no temporary file left behind.
TEST(Cli, AnOutputNameTakenByADirectoryIsSaidPlainly) {
  TempDir dir;
  const auto s = dir.write("s.toml", scenario("", "", "spp = 1"));
  std::filesystem::create_directories(dir / "out" / "v.exr");
  const Result r = run("render " + s.string() + " --out " + (dir / "out").string(), dir);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("error: cannot write"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("v.exr: Is a directory"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("internal error"), std::string::npos) << r.err;
  EXPECT_EQ(testing::file_names(dir / "out"), std::set<std::string>{"v.exr"});
}

// A set whose second image fails: the first image keeps a manifest that lists it and says
// the set is unfinished (before, the set had images and no manifest).
TEST(Cli, ALaterImageThatFailsLeavesAManifestOfTheFinishedOnes) {
  TempDir dir;
  const auto s =
      dir.write("s.toml", scenario("",
                                   "[[views]]\nname = \"w\"\nposition = [500.0, 900.0, 330.0]\n"
                                   "target = [280.0, 280.0, 130.0]\nwidth = 32\nheight = 18\n",
                                   "spp = 1"));
  std::filesystem::create_directories(dir / "out" / "w.exr");
  const Result r = run("render " + s.string() + " --out " + (dir / "out").string(), dir);
  EXPECT_EQ(r.exit_code, 1) << r.err;
  ASSERT_TRUE(std::filesystem::exists(dir / "out" / "manifest.json")) << r.err;
  const auto manifest = nlohmann::json::parse(std::ifstream(dir / "out" / "manifest.json"));
  EXPECT_FALSE(manifest["complete"].get<bool>());
  ASSERT_EQ(manifest["images"].size(), 1u);
  EXPECT_EQ(manifest["images"][0]["view"], "v");
  EXPECT_TRUE(std::filesystem::exists(dir / "out" / "v.exr"));
}

TEST(CliTree, PrintsTheJsonContract) {
  TempDir dir;
  // The California black oak splits (clones): every count must be the library's own tree's.
  const auto file = testing::source_file("data/species/ca_black_oak.xml").string();
  const auto start = std::chrono::steady_clock::now();
  const Result r = run("tree " + file + " --seed 13 --json", dir);
  const double wall_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  const trees::Species species = trees::load_species(file);
  const trees::Tree tree = trees::generate(species, {.seed = 13});
  EXPECT_EQ(j["species"], species.name);
  EXPECT_EQ(j["core"], "weber_penn");
  EXPECT_EQ(j["seed"], 13);
  const auto& per_level = j["stems"]["per_level"];
  ASSERT_EQ(per_level.size(), tree.stats.stems_per_level.size());
  int total = 0;
  for (std::size_t k = 0; k < per_level.size(); ++k) {
    EXPECT_EQ(per_level[k].get<int>(), tree.stats.stems_per_level[k]) << "level " << k;
    total += tree.stats.stems_per_level[k];
  }
  EXPECT_EQ(j["stems"]["total"].get<int>(), total);
  EXPECT_GT(tree.stats.clones, 0);
  EXPECT_EQ(j["stems"]["clones"].get<int>(), tree.stats.clones);
  EXPECT_EQ(j["leaves"].get<int>(), tree.stats.leaves);
  EXPECT_EQ(j["triangles"].get<std::size_t>(), tree.geometry.triangle_count());
  EXPECT_DOUBLE_EQ(j["height_m"].get<double>(), tree.stats.height);
  EXPECT_DOUBLE_EQ(j["crown_radius_m"].get<double>(), tree.stats.crown_radius);
  // The generation's time: some of the program's wall time, never all of it.
  EXPECT_GT(j["generate_ms"].get<double>(), 0.0);
  EXPECT_LT(j["generate_ms"].get<double>(), wall_ms);
}

TEST(CliTree, WritesAValidObj) {
  TempDir dir;
  const auto species = testing::source_file("data/species/palm.xml").string();
  const auto obj = dir / "palm.obj";
  const Result r = run("tree " + species + " --obj " + obj.string() + " --json", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  std::istringstream in(testing::read_file(obj));
  std::string line;
  long vertices = 0, normals = 0, faces = 0;
  bool indices_ok = true;
  while (std::getline(in, line)) {
    if (line.rfind("v ", 0) == 0) ++vertices;
    if (line.rfind("vn ", 0) == 0) ++normals;
    if (line.rfind("f ", 0) == 0) {
      ++faces;
      std::istringstream f(line.substr(2));
      std::string corner;
      while (f >> corner) {
        const long index = std::stol(corner.substr(0, corner.find('/')));
        indices_ok = indices_ok && index >= 1 && index <= vertices;
      }
    }
  }
  EXPECT_EQ(faces, j["triangles"].get<long>());
  EXPECT_EQ(vertices, normals);
  EXPECT_TRUE(indices_ok);
}

TEST(CliTree, BadSpeciesFilesExitTwoNamingTheParameter) {
  TempDir dir;
  const auto bad = dir.write("bad.toml", "core = \"weber_penn\"\nLevels = 3\n2CurveRes = 500\n");
  const Result r = run("tree " + bad.string() + " --obj " + (dir / "t.obj").string(), dir);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("2CurveRes"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("bad.toml:3"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "t.obj"));
  const auto boom =
      dir.write("boom.xml",
                "<arbaro><species name='boom'><param name='Levels' value='4'/>"
                "<param name='1Branches' value='900'/><param name='2Branches' value='900'/>"
                "</species></arbaro>");
  const Result b = run("tree " + boom.string(), dir);
  EXPECT_EQ(b.exit_code, 2);
  EXPECT_NE(b.err.find("limit"), std::string::npos) << b.err;
  EXPECT_EQ(run("tree /no/such/species.toml", dir).exit_code, 2);
}

TEST(CliTree, GraphPathsSpeciesGenerateAndBadShapesExitTwo) {
  TempDir dir;
  const auto species = testing::source_file("data/species/graph_round_crown.toml").string();
  const Result r = run("tree " + species + " --seed 4 --json", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["core"], "graph_paths");
  EXPECT_GT(j["stems"]["total"].get<int>(), 50);
  EXPECT_GT(j["height_m"].get<double>(), 5.0);
  const auto bad = dir.write("bad.toml", "core = \"graph_paths\"\n[[volume]]\nkind = \"torus\"\n");
  const Result b = run("tree " + bad.string() + " --obj " + (dir / "t.obj").string(), dir);
  EXPECT_EQ(b.exit_code, 2);
  EXPECT_NE(b.err.find("bad.toml:3:"), std::string::npos) << b.err;
  EXPECT_NE(b.err.find("[volume[0]] kind"), std::string::npos) << b.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "t.obj"));
}

TEST(CliDegrade, PrintsTable2AsJsonFollowingTheEquations) {
  TempDir dir;
  const auto species = testing::source_file("data/species/quaking_aspen.toml").string();
  const Result r = run("degrade " + species + " --paper --json", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["species"], "quaking_aspen");
  const auto& rows = j["rows"];
  ASSERT_EQ(rows.size(), 7u);  // the paper's seven ranges by default
  const std::set<std::string> keys = {
      "range_m",          "r2",           "trunk_triangles",  "trunk_lines",
      "level1_triangles", "level1_lines", "level2_triangles", "level2_lines",
      "leaf_triangles",   "leaf_points"};
  for (const auto& row : rows) {
    std::set<std::string> have;
    for (const auto& [k, v] : row.items()) have.insert(k);
    EXPECT_EQ(have, keys);
    EXPECT_DOUBLE_EQ(row["r2"].get<double>(), row["range_m"].get<double>());  // --paper
  }
  const auto at = [&](std::size_t k, const char* key) { return rows[k][key].get<long>(); };
  // Ranges 5, 30, 60, 120, 240, 600, 1200: Table 2's pattern.
  EXPECT_EQ(at(2, "trunk_lines"), 0);  // r2 < 100
  EXPECT_GT(at(3, "trunk_lines"), 0);
  EXPECT_EQ(at(6, "trunk_triangles"), 0);  // past 800
  EXPECT_GT(at(5, "trunk_triangles"), 0);  // 300 < r2 < 800: thinning
  EXPECT_LT(at(5, "trunk_triangles"), at(0, "trunk_triangles"));
  EXPECT_EQ(at(3, "level1_triangles"), 0);                          // past 200 s = 100
  EXPECT_EQ(at(6, "level1_lines"), 0);                              // past 2000 s = 1000
  EXPECT_EQ(at(2, "level2_triangles"), 0);                          // past 100 s = 50
  EXPECT_EQ(at(4, "leaf_triangles"), 0);                            // past d = 200
  EXPECT_EQ(at(6, "leaf_points"), (at(0, "leaf_points") + 3) / 4);  // one per mass of 4
  // Without --paper, 1080 px and 40 degrees make everything happen farther away.
  const Result hd = run("degrade " + species + " --ranges 240 --json", dir);
  ASSERT_EQ(hd.exit_code, 0) << hd.err;
  const auto h = nlohmann::json::parse(hd.out)["rows"][0];
  EXPECT_NEAR(h["r2"].get<double>(), 240.0 * 1000.0 / 1080.0 * 40.0 / 60.0, 1e-6);
  EXPECT_GT(h["leaf_triangles"].get<long>(), 0);
  EXPECT_EQ(run("degrade " + species + " --season monsoon", dir).exit_code, 2);
}

TEST(CliPlate, WritesOnePanelPerRange) {
  TempDir dir;
  const auto species = testing::source_file("data/species/quaking_aspen.toml").string();
  const auto out = dir / "plate.png";
  const Result r = run(
      "plate " + species + " --out " + out.string() + " --ranges 60,600 --tile 64 --spp 1", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  auto in = OIIO::ImageInput::open(out.string());
  ASSERT_TRUE(in);
  EXPECT_EQ(in->spec().width, 128);
  EXPECT_EQ(in->spec().height, 64);
  EXPECT_EQ(
      run("plate " + species + " --out " + (dir / "x.png").string() + " --tile 0", dir).exit_code,
      2);
  EXPECT_FALSE(std::filesystem::exists(dir / "x.png"));
}

}  // namespace
}  // namespace landsim
