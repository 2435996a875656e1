// scenes/ is three folders whose includes run one way (docs/ARCHITECTURE.md): reading a
// scenario (scenario/) knows nothing of building or of files written, and never of Embree;
// building a scene (builder/) knows nothing of the image set's files. Checked on the sources.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

const fs::path kScenes = fs::path(LANDSIM_SOURCE_DIR) / "scenes";

struct Include {
  fs::path file;
  std::string header;
};

std::vector<fs::path> sources(const fs::path& folder) {
  std::vector<fs::path> out;
  for (const auto& e : fs::recursive_directory_iterator(folder)) {
    const std::string ext = e.path().extension().string();
    if (ext == ".h" || ext == ".cpp") out.push_back(e.path());
  }
  return out;
}

std::vector<Include> includes(const fs::path& folder) {
  static const std::regex kInclude(R"(^\s*#\s*include\s*[<"]([^>"]+)[>"])");
  std::vector<Include> out;
  for (const fs::path& f : sources(folder)) {
    std::ifstream in(f);
    std::string line;
    std::smatch m;
    while (std::getline(in, line))
      if (std::regex_search(line, m, kInclude)) out.push_back({f, m[1].str()});
  }
  return out;
}

// The includes of `folder` that start with any of `forbidden`, as "file: header" lines.
std::vector<std::string> crossing(const std::string& folder,
                                  const std::vector<std::string>& forbidden) {
  std::vector<std::string> out;
  for (const Include& i : includes(kScenes / folder))
    for (const std::string& prefix : forbidden)
      if (i.header.rfind(prefix, 0) == 0)
        out.push_back(fs::relative(i.file, kScenes).string() + ": " + i.header);
  return out;
}

TEST(ScenesLayering, TheFoldersAreThere) {
  for (const char* folder : {"scenario", "builder", "image_set"}) {
    EXPECT_TRUE(fs::is_directory(kScenes / folder)) << folder;
    EXPECT_FALSE(sources(kScenes / folder).empty()) << folder;
  }
  // Nothing left at scenes/'s top level but the folders (and the example scenarios).
  for (const auto& e : fs::directory_iterator(kScenes))
    EXPECT_FALSE(e.path().extension() == ".h" || e.path().extension() == ".cpp") << e.path();
}

TEST(ScenesLayering, ReadingAScenarioNeedsNeitherBuildingNorFilesNorEmbree) {
  EXPECT_EQ(crossing("scenario", {"scenes/builder/", "scenes/image_set/", "embree",
                                  "renderer/acceleration/", "renderer/transport/"}),
            std::vector<std::string>{});
}

TEST(ScenesLayering, BuildingASceneKnowsNothingOfTheImageSet) {
  EXPECT_EQ(crossing("builder", {"scenes/image_set/", "renderer/output/exposure.h",
                                 "renderer/output/image_output.h"}),
            std::vector<std::string>{});
}

TEST(ScenesLayering, NoFileOverFiveHundredLines) {
  for (const fs::path& f : sources(kScenes)) {
    std::ifstream in(f);
    int lines = 0;
    for (std::string line; std::getline(in, line);) ++lines;
    EXPECT_LE(lines, 500) << fs::relative(f, kScenes).string();
  }
}

}  // namespace
