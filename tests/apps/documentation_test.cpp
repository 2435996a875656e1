// The documentation cites tests by name (`Suite.Name`, or `Suite.*` for a whole suite) as the
// evidence for what it states: every cited test must exist, so a renamed or removed test
// cannot leave a claim pointing at nothing.
#include <gtest/gtest.h>

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

TEST(Documentation, EveryCitedTestExists) {
  const std::set<std::string> defined = defined_tests();
  ASSERT_GT(defined.size(), 500u);
  std::vector<fs::path> documents = {testing::source_file("README.md")};
  for (const auto& e : fs::directory_iterator(testing::source_file("docs")))
    if (e.path().extension() == ".md") documents.push_back(e.path());
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

}  // namespace
}  // namespace landsim
