// The documentation cites tests by name (`Suite.Name`, or `Suite.*` for a whole suite) as the
// evidence for what it states: every cited test must exist, so a renamed or removed test
// cannot leave a claim pointing at nothing.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <regex>
#include <set>
#include <string>

#include "tests/support/temp_dir.h"

namespace landsim {
namespace {

namespace fs = std::filesystem;

// Every test's "Suite.Name" and "Suite.*" in the test sources (plain, fixture and
// parameterised tests alike).
std::set<std::string> defined_tests() {
  std::set<std::string> names;
  const std::regex test(R"(\bTEST(?:_F|_P)?\(\s*(\w+)\s*,\s*(\w+)\s*\))");
  for (const auto& e : fs::recursive_directory_iterator(testing::source_file("tests"))) {
    if (e.path().extension() != ".cpp") continue;
    const std::string text = testing::read_file(e.path());
    for (auto it = std::sregex_iterator(text.begin(), text.end(), test);
         it != std::sregex_iterator(); ++it) {
      names.insert((*it)[1].str() + "." + (*it)[2].str());
      names.insert((*it)[1].str() + ".*");
    }
  }
  return names;
}

// The project's pages: the README, docs/, and each folder's README beside its code.
std::vector<fs::path> documents() {
  std::vector<fs::path> out = {testing::source_file("README.md")};
  for (const auto& e : fs::directory_iterator(testing::source_file("docs")))
    if (e.path().extension() == ".md") out.push_back(e.path());
  const fs::path root = testing::source_file("");
  for (auto it = fs::recursive_directory_iterator(root); it != fs::recursive_directory_iterator();
       ++it) {
    const std::string name = it->path().filename().string();
    // Build trees, hidden folders and data (third-party READMEs) are not the project's pages.
    if (it->is_directory() && (name.rfind("build", 0) == 0 || name[0] == '.' || name == "data")) {
      it.disable_recursion_pending();
      continue;
    }
    if (name == "README.md" && fs::relative(it->path(), root) != "README.md")
      out.push_back(it->path());
  }
  return out;
}

TEST(Documentation, EveryCitedTestExists) {
  const std::set<std::string> defined = defined_tests();
  ASSERT_GT(defined.size(), 500u);
  const std::vector<fs::path> documents = ::landsim::documents();
  ASSERT_GT(documents.size(), 30u);
  const std::regex cited("`([A-Z]\\w+)\\.([A-Z]\\w+|\\*)`");
  int citations = 0;
  for (const fs::path& doc : documents) {
    const std::string text = testing::read_file(doc);
    for (auto it = std::sregex_iterator(text.begin(), text.end(), cited);
         it != std::sregex_iterator(); ++it) {
      const std::string name = (*it)[1].str() + "." + (*it)[2].str();
      ++citations;
      EXPECT_TRUE(defined.count(name))
          << doc.filename().string() << " cites " << name << ", which no test defines";
    }
  }
  EXPECT_GT(citations, 50);
}

// A link to a file of the project leads to one (a page moved or renamed leaves none behind).
TEST(Documentation, EveryLocalLinkLeadsToAFile) {
  const std::regex link(R"(\]\(([^)#\s]+)(#[^)\s]*)?\))");
  int links = 0;
  for (const fs::path& doc : documents()) {
    const std::string text = testing::read_file(doc);
    for (auto it = std::sregex_iterator(text.begin(), text.end(), link);
         it != std::sregex_iterator(); ++it) {
      const std::string target = (*it)[1].str();
      if (target.find("://") != std::string::npos || target.rfind("mailto:", 0) == 0) continue;
      ++links;
      EXPECT_TRUE(fs::exists(doc.parent_path() / target))
          << fs::relative(doc, testing::source_file("")).string() << " links to " << target
          << ", which is not there";
    }
  }
  EXPECT_GT(links, 30);
}

// docs/ARCHITECTURE.md is read in five minutes: two screens, every folder named.
TEST(Documentation, TheArchitecturePageNamesEveryFolderOnTwoScreens) {
  const std::string text = testing::read_file(testing::source_file("docs/ARCHITECTURE.md"));
  EXPECT_LE(std::count(text.begin(), text.end(), '\n'), 100);
  for (const char* folder :
       {"core/", "params/", "terrain/", "featuremaps/", "trees/", "renderer/", "scenes/scenario/",
        "scenes/builder/", "scenes/image_set/", "exporters/", "apps/landsim/", "python/",
        "modules/", "fuzz/", "tests/", "bench/", "data/", "scripts/", "docs/"})
    EXPECT_NE(text.find(std::string("`") + folder + "`"), std::string::npos) << folder;
}

// The README's first screen: the two commands first, then what landsim is, with pictures.
TEST(Documentation, TheReadmeOpensWithTheTwoCommandsAndShowsWhatLandsimMakes) {
  const std::string text = testing::read_file(testing::source_file("README.md"));
  const std::size_t fence = text.find("```sh\n");
  ASSERT_NE(fence, std::string::npos);
  const std::size_t end = text.find("```", fence + 6);
  const std::string commands = text.substr(fence + 6, end - fence - 6);
  EXPECT_EQ(std::count(commands.begin(), commands.end(), '\n'), 2) << commands;
  EXPECT_NE(commands.find("landsim render"), std::string::npos);
  EXPECT_NE(commands.find("ctest"), std::string::npos);
  // Within the first 40 lines: at least three pictures.
  std::size_t at = 0;
  for (int line = 0; line < 40 && at != std::string::npos; ++line) at = text.find('\n', at + 1);
  const std::string first_screen = text.substr(0, at);
  int pictures = 0;
  for (std::size_t p = first_screen.find("]("); p != std::string::npos;
       p = first_screen.find("](", p + 1))
    pictures += first_screen.compare(p + 2, 12, "docs/images/") == 0 ? 1 : 0;
  EXPECT_GE(pictures, 3);
}

}  // namespace
}  // namespace landsim
