// docs/JSON.md is the contract of every command's --json output: each command is run and
// its keys compared with the documented ones, in both directions.
#include <gtest/gtest.h>

#include <map>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>
#include <sstream>

#include "tests/support/run_program.h"
#include "tests/support/temp_dir.h"
#include "tests/support/tools.h"

namespace landsim {
namespace {

using testing::TempDir;

struct DocumentedKey {
  std::regex pattern;  // `<name>` segments match any key
  bool optional = false;
};

// The documented keys of "## landsim COMMAND --json", by path.
std::map<std::string, DocumentedKey> documented(const std::string& command) {
  const std::string doc = testing::read_file(testing::source_file("docs/JSON.md"));
  const std::string heading = "## landsim " + command + " --json";
  const std::size_t start = doc.find(heading);
  EXPECT_NE(start, std::string::npos) << heading;
  const std::size_t end = doc.find("\n## ", start + heading.size());
  std::istringstream lines(doc.substr(start, end - start));
  std::map<std::string, DocumentedKey> keys;
  const std::regex name("`([^`]+)`");
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("| `", 0) != 0) continue;
    const std::size_t first_end = line.find(" |", 2);
    const std::string cell = line.substr(2, first_end - 2);
    const bool optional = line.find("*optional*") != std::string::npos;
    for (auto it = std::sregex_iterator(cell.begin(), cell.end(), name);
         it != std::sregex_iterator(); ++it) {
      const std::string path = (*it)[1];
      std::string pattern = std::regex_replace(path, std::regex(R"([.\[\]])"), R"(\$&)");
      pattern = std::regex_replace(pattern, std::regex("<[a-z_]+>"), "[^.]+");
      keys[path] = {std::regex(pattern), optional};
    }
  }
  EXPECT_FALSE(keys.empty()) << heading;
  return keys;
}

// Every key path of `v`: "a", "a.b", "a[].b" (over all objects of array a).
void flatten(const nlohmann::json& v, const std::string& prefix, std::set<std::string>& out) {
  if (v.is_object()) {
    for (const auto& [k, x] : v.items()) {
      const std::string path = prefix.empty() ? k : prefix + "." + k;
      out.insert(path);
      flatten(x, path, out);
    }
  } else if (v.is_array()) {
    for (const auto& x : v)
      if (x.is_object()) flatten(x, prefix + "[]", out);
  }
}

void expect_contract(const std::string& command, const std::string& args, const TempDir& dir) {
  const testing::ProgramResult r = testing::run_landsim(command + " " + args + " --json", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::set<std::string> actual;
  flatten(nlohmann::json::parse(r.out), "", actual);
  const std::map<std::string, DocumentedKey> keys = documented(command);
  for (const std::string& path : actual) {
    bool found = false;
    for (const auto& [doc_path, key] : keys) found = found || std::regex_match(path, key.pattern);
    EXPECT_TRUE(found) << command << " --json prints " << path << ", not in docs/JSON.md";
  }
  for (const auto& [doc_path, key] : keys) {
    if (key.optional || doc_path.find('<') != std::string::npos) continue;
    // A key inside an object the output leaves out (an optional one, such as brf's budget in
    // a monochromatic run) is not missing.
    const std::size_t dot = doc_path.rfind('.');
    std::string parent = dot == std::string::npos ? "" : doc_path.substr(0, dot);
    if (parent.size() > 2 && parent.ends_with("[]")) parent.resize(parent.size() - 2);
    if (!parent.empty() && !actual.count(parent) && !actual.count(parent + "[]")) continue;
    EXPECT_TRUE(actual.count(doc_path))
        << "docs/JSON.md documents " << doc_path << " for " << command << "; it is missing";
  }
}

std::string species(const std::string& file) {
  return testing::source_file("data/species/" + file).string();
}

TEST(JsonContract, Render) {
  TempDir dir;
  expect_contract("render", "--spp 1 --width 32 --out " + (dir / "r").string(), dir);
}

TEST(JsonContract, Brf) {
  TempDir dir;
  expect_contract("brf",
                  testing::source_file("scenes/rami/het01.toml").string() +
                      " --direction 0,0 --direction 30,90 --spp 16",
                  dir);
}

// At the bottom of the one atmosphere: the HDRF in place of the BRF, and the BHR.
TEST(JsonContract, BrfAtTheBottomOfTheAtmosphere) {
  TempDir dir;
  expect_contract("brf",
                  testing::source_file("scenes/rami4atm/hom00_whi_s00s_m04.toml").string() +
                      " --level boa --direction 0,0 --spp 64 --budget-paths 1000",
                  dir);
}

// Monochromatic runs: each wavelength a band, `wavelengths_nm`, the luminance null.
TEST(JsonContract, BrfMonochromatic) {
  TempDir dir;
  expect_contract("brf",
                  testing::source_file("scenes/rami4atm/hom00_bla_sd2s_m03.toml").string() +
                      " --direction 0,0 --spp 64 --wavelength 550,560",
                  dir);
}

TEST(JsonContract, Info) {
  TempDir dir;
  expect_contract("info", "", dir);
}

TEST(JsonContract, Tree) {
  TempDir dir;
  expect_contract("tree", species("quaking_aspen.toml"), dir);
}

TEST(JsonContract, Degrade) {
  TempDir dir;
  expect_contract("degrade", species("quaking_aspen.toml"), dir);
}

TEST(JsonContract, Grow) {
  TempDir dir;
  expect_contract("grow", species("london_plane.toml") + " --ages 10 --out " + (dir / "g").string(),
                  dir);
  expect_contract("grow",
                  species("harmonic_cherry.toml") +
                      " --ages 10 --width 32 --height 32 --spp 1 "
                      "--out " +
                      (dir / "h").string(),
                  dir);
}

TEST(JsonContract, Discover) {
  TempDir dir;
  expect_contract("discover", "--count 2 --out " + (dir / "d.png").string(), dir);
}

TEST(JsonContract, Crosscheck) {
  LANDSIM_REQUIRE_TOOL("povray", "povray");
  TempDir dir;
  const auto file =
      dir.write("s.toml", "[terrain]\nelevation = \"" +
                              testing::source_file("data/terrain/volcano.asc").string() +
                              "\"\n[sun]\nelevation = 30\nazimuth = 300\n[[views]]\nname = \"v\"\n"
                              "position = [500.0, 900.0, 330.0]\ntarget = [280.0, 280.0, 130.0]\n"
                              "width = 32\nheight = 18\n");
  expect_contract("crosscheck", file.string() + " --spp 1 --out " + (dir / "c").string(), dir);
  // With --pov the camera it read is reported too.
  ASSERT_EQ(
      testing::run_landsim("export-pov " + file.string() + " --out " + (dir / "p").string(), dir)
          .exit_code,
      0);
  expect_contract("crosscheck",
                  file.string() + " --spp 1 --out " + (dir / "d").string() + " --pov " +
                      (dir / "p" / "scene.pov").string(),
                  dir);
}

TEST(JsonContract, Compare) {
  TempDir dir;
  const auto set = dir / "set";
  // Two samples: the variance layer, and so the noise test's keys.
  ASSERT_EQ(testing::run_landsim("render --spp 2 --width 32 --out " + set.string(), dir).exit_code,
            0);
  expect_contract("compare", set.string() + " " + set.string(), dir);
}

TEST(JsonContract, Sense) {
  TempDir dir;
  const auto set = dir / "set";
  ASSERT_EQ(testing::run_landsim(
                "render --spp 1 --width 32 --set sensor.adc_bits=12 --out " + set.string(), dir)
                .exit_code,
            0);
  expect_contract("sense", set.string() + " --noise-seed 3", dir);
}

TEST(JsonContract, Annotate) {
  TempDir dir;
  const auto set = dir / "set";
  ASSERT_EQ(testing::run_landsim("render --spp 1 --width 32 --out " + set.string(), dir).exit_code,
            0);
  expect_contract("annotate", set.string() + " --format yolo", dir);
  // Several formats in one call, each in its own folder.
  const testing::ProgramResult r =
      testing::run_landsim("annotate " + set.string() + " --format coco,kitti,yolo --json", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["formats"].size(), 3u);
  for (const char* format : {"coco", "kitti", "yolo"})
    EXPECT_TRUE(std::filesystem::is_directory(set / format)) << format;
  EXPECT_TRUE(std::filesystem::exists(set / "coco" / "annotations.json"));
  EXPECT_TRUE(std::filesystem::exists(set / "yolo" / "classes.txt"));
}

}  // namespace
}  // namespace landsim
