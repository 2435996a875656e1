// docs/SPECIES.md (and HARMONIC.md for the harmonic blocks) against what the cores declare:
// every key a core reads from its example species files is documented in its section, and
// every documented key is one a core reads. The declarations come from the one parameter
// reader (params::TableReader) while the files are parsed.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <regex>
#include <set>
#include <sstream>
#include <vector>

#include "params/table_reader.h"
#include "tests/support/temp_dir.h"
#include "trees/species.h"

namespace landsim::trees {
namespace {

using landsim::testing::read_file;
using landsim::testing::source_file;

// Keys the example files of a core declare, written as docs/SPECIES.md writes them:
// "[graph] spacing", "[[volume]] kind", "[allometry.dbh]" (equation tables as a whole), and
// top-level values ("general") bare. The shared keys (core, name, colours) are documented
// once, under Formats.
// What the reader declares while it parses every example file whose name starts with
// `file_prefix`; a table inside an array of tables ("phase[0].direction") as
// "phase.direction".
params::Declarations declarations_of(const std::string& file_prefix) {
  params::Declarations all;
  for (const auto& entry : std::filesystem::directory_iterator(source_file("data/species"))) {
    const std::string name = entry.path().filename().string();
    if (name.rfind(file_prefix, 0) != 0 || entry.path().extension() != ".toml") continue;
    params::Declarations declared;
    parse_species_toml(read_file(entry.path()), entry.path().string(), &declared);
    for (params::KeyDeclaration& d : declared) {
      d.table = std::regex_replace(d.table, std::regex(R"(\[\d*\]\.)"), ".");
      all.push_back(d);
    }
  }
  return all;
}

std::set<std::string> declared_keys(const std::string& file_prefix) {
  std::set<std::string> keys;
  for (const params::KeyDeclaration& d : declarations_of(file_prefix)) {
    if (d.table.empty() && (d.key == "core" || d.key == "name" || d.key == "colours")) continue;
    if (d.table == "colours") continue;
    if (d.table.rfind("allometry.", 0) == 0) {
      keys.insert("[" + d.table + "]");
    } else if (d.table.size() > 2 && d.table.substr(d.table.size() - 2) == "[]") {
      keys.insert("[[" + d.table.substr(0, d.table.size() - 2) + "]] " + d.key);
    } else if (d.table.empty()) {
      if (d.key != "allometry") keys.insert(d.key);
    } else {
      keys.insert("[" + d.table + "] " + d.key);
    }
  }
  return keys;
}

// The keys of the tables in the section of `doc` that starts at `heading`, one per backquoted
// name in the first column; "[t] a, `b`" documents "[t] a" and "[t] b".
std::set<std::string> documented_keys(const std::string& doc, const std::string& heading) {
  const std::size_t start = doc.find(heading);
  EXPECT_NE(start, std::string::npos) << heading;
  const std::size_t end = doc.find("\n## ", start + heading.size());
  std::istringstream lines(doc.substr(start, end - start));
  std::set<std::string> keys;
  const std::regex name("`([^`]+)`");
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("| `", 0) != 0) continue;
    const std::string cell = line.substr(2, line.find(" |", 2) - 2);
    std::string table;
    for (auto it = std::sregex_iterator(cell.begin(), cell.end(), name);
         it != std::sregex_iterator(); ++it) {
      std::string key = (*it)[1];
      const std::size_t space = key.rfind("] ");
      if (space != std::string::npos) {
        table = key.substr(0, space + 1);
      } else if (!table.empty() && key.front() != '[') {
        key = table + " " + key;
      }
      keys.insert(key);
    }
  }
  return keys;
}

void expect_documented(const std::string& doc_file, const std::string& heading,
                       const std::string& file_prefix, const std::set<std::string>& aliases = {}) {
  const std::set<std::string> declared = declared_keys(file_prefix);
  ASSERT_FALSE(declared.empty()) << file_prefix;
  const std::set<std::string> documented =
      documented_keys(read_file(source_file(doc_file)), heading);
  for (const std::string& k : declared)
    EXPECT_TRUE(documented.count(k)) << k << " is read but not documented in " << doc_file;
  for (const std::string& k : documented)
    EXPECT_TRUE(declared.count(k) || aliases.count(k))
        << k << " is documented in " << doc_file << " but no example declares it";
}

// The numbers of a text: unsigned decimals and exponents ("0.25-20" gives 0.25 and 20).
std::vector<double> numbers_in(const std::string& text) {
  static const std::regex number(R"((\d+(\.\d+)?(e-?\d+)?))");
  std::vector<double> out;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), number);
       it != std::sregex_iterator(); ++it)
    out.push_back(std::stod((*it)[1]));
  return out;
}

// Every range a reader enforces ("a number from 0.001 to 1", "an integer from 0 to 64") is
// given in the key's row of `doc_file` (its second column, as "0.001-1"): a user sees the
// limits before the reader refuses a value.
void expect_ranges_documented(const std::string& doc_file, const std::string& heading,
                              const std::string& file_prefix) {
  const std::string doc = read_file(source_file(doc_file));
  const std::size_t start = doc.find(heading);
  ASSERT_NE(start, std::string::npos) << heading;
  const std::string section = doc.substr(start, doc.find("\n## ", start + 1) - start);
  static const std::regex range(R"(from (-?[\d.e-]+)(?: \(exclusive\))? to (-?[\d.e-]+))");
  for (const params::KeyDeclaration& d : declarations_of(file_prefix)) {
    std::smatch m;
    if (!std::regex_search(d.expected, m, range)) continue;
    const bool array = d.table.size() > 2 && d.table.substr(d.table.size() - 2) == "[]";
    const std::string table =
        array ? "[[" + d.table.substr(0, d.table.size() - 2) + "]]" : "[" + d.table + "]";
    // The row that names the key: "| `[t] key`" or "| `[t] a`, `key`".
    std::istringstream lines(section);
    std::string row;
    for (std::string line; std::getline(lines, line) && row.empty();) {
      if (line.rfind("| `", 0) != 0) continue;
      const std::string first = line.substr(2, line.find(" | ", 2) - 2);
      if (first.find("`" + table + " " + d.key + "`") != std::string::npos ||
          (first.rfind("`" + table + " ", 0) == 0 &&
           first.find("`" + d.key + "`") != std::string::npos))
        row = line;
    }
    if (row.empty()) continue;  // the key's documentation is held by the test above
    const std::size_t second = row.find(" | ") + 3;
    const std::string unit = row.substr(second, row.find(" | ", second) - second);
    if (unit.rfind("as ", 0) == 0) continue;  // "as `[vigour]`": that table's ranges
    const std::vector<double> given = numbers_in(unit);
    for (const double bound : {std::abs(std::stod(m[1])), std::abs(std::stod(m[2]))}) {
      const bool found = std::any_of(given.begin(), given.end(), [&](double g) {
        return std::abs(g - bound) <= 1e-9 * std::max(1.0, bound);
      });
      EXPECT_TRUE(found) << doc_file << ": " << table << " " << d.key << " enforces " << d.expected
                         << " but its row gives \"" << unit << "\"";
    }
  }
}

TEST(SpeciesDocs, EveryEnforcedRangeIsDocumented) {
  expect_ranges_documented("docs/SPECIES.md", "## Graph-paths species", "graph_");
  expect_ranges_documented("docs/SPECIES.md", "## Self-organising species", "so_");
  expect_ranges_documented("docs/SPECIES.md", "## Measured-growth species", "london_plane");
}

TEST(SpeciesDocs, GraphPathsKeysAreTheDocumentedOnes) {
  expect_documented("docs/SPECIES.md", "## Graph-paths species", "graph_");
}

// `age` is the documented other name of `steps`; the constraints, strokes and prunings are
// documented though the examples that use them are tests' own files.
TEST(SpeciesDocs, SelfOrganizingKeysAreTheDocumentedOnes) {
  expect_documented("docs/SPECIES.md", "## Self-organising species", "so_",
                    {"[growth] age", "[[width_constraint]] internode", "[[width_constraint]] width",
                     "[[stroke]] points", "[[stroke]] start_step", "[[stroke]] points_per_step",
                     "[[stroke]] markers_per_step", "[[stroke]] max_age", "[[prune]] step",
                     "[[prune]] at", "[[prune]] stub", "[[phase]] from_step",
                     "[[phase]] select"});
}

TEST(SpeciesDocs, MeasuredGrowthKeysAreTheDocumentedOnes) {
  expect_documented("docs/SPECIES.md", "## Measured-growth species", "london_plane");
}

TEST(SpeciesDocs, HarmonicBlocksAreTheDocumentedOnes) {
  expect_documented("docs/HARMONIC.md", "| block (species-file key)", "harmonic_");
}

// Weber & Penn's parameters are documented by name, per-level ones once as "nName".
TEST(SpeciesDocs, WeberPennParametersAreTheDocumentedOnes) {
  params::Declarations declared;
  const auto file = source_file("data/species/quaking_aspen.toml");
  parse_species_toml(read_file(file), file.string(), &declared);
  std::set<std::string> names;
  for (const params::KeyDeclaration& d : declared) {
    if (d.key == "core" || d.key == "name" || d.key == "colours" || !d.table.empty()) continue;
    names.insert(std::isdigit(static_cast<unsigned char>(d.key.front())) != 0 &&
                         d.key.find("Scale") == std::string::npos &&
                         d.key.find("BaseSplits") == std::string::npos
                     ? "n" + d.key.substr(1)
                     : d.key);
  }
  ASSERT_GT(names.size(), 40u);
  const std::string doc = read_file(source_file("docs/SPECIES.md"));
  const std::size_t start = doc.find("## Weber & Penn parameters");
  ASSERT_NE(start, std::string::npos);
  std::istringstream lines(doc.substr(start, doc.find("\n## ", start + 1) - start));
  std::set<std::string> documented;
  const std::regex name(R"([A-Za-z0-9]+)");
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("| ", 0) != 0 || line.rfind("| parameter", 0) == 0 || line.rfind("|---", 0) == 0)
      continue;
    const std::string cell = line.substr(2, line.find(" |", 2) - 2);
    for (auto it = std::sregex_iterator(cell.begin(), cell.end(), name);
         it != std::sregex_iterator(); ++it)
      documented.insert((*it)[0]);
  }
  for (const std::string& n : names)
    EXPECT_TRUE(documented.count(n)) << n << " is read but not in docs/SPECIES.md";
  for (const std::string& n : documented)
    EXPECT_TRUE(names.count(n)) << n << " is documented but not a Weber & Penn parameter";
}

}  // namespace
}  // namespace landsim::trees
