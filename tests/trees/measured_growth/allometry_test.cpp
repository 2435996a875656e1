#include "trees/measured_growth/allometry.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "tests/support/temp_dir.h"
#include "trees/measured_growth/parameters.h"
#include "trees/species.h"

namespace landsim::trees::measured_growth {
namespace {

// The InlVal (Modesto) rows of the database file, by predicted component.
std::map<std::string, std::vector<std::string>> modesto_rows() {
  std::ifstream in(testing::source_file("data/allometry/platanus_x_acerifolia_utd_equations.csv"));
  std::map<std::string, std::vector<std::string>> rows;
  std::string line;
  while (std::getline(in, line)) {
    std::vector<std::string> cells;
    std::stringstream ss(line);
    std::string cell;
    while (std::getline(ss, cell, ',')) cells.push_back(cell);
    if (cells.size() > 14 && cells[0] == "InlVal") rows[cells[4]] = cells;
  }
  return rows;
}

void expect_row(const std::vector<std::string>& row, const Equation& e) {
  ASSERT_GE(row.size(), 15u);
  ModelForm form{};
  ASSERT_TRUE(parse_form(row[7], form)) << row[7];
  EXPECT_EQ(form, e.form) << row[4];
  const auto number = [](const std::string& s) { return s.empty() ? 0.0 : std::stod(s); };
  EXPECT_DOUBLE_EQ(number(row[8]), e.a) << row[4];
  EXPECT_DOUBLE_EQ(number(row[9]), e.b) << row[4];
  EXPECT_DOUBLE_EQ(number(row[10]), e.c) << row[4];
  EXPECT_DOUBLE_EQ(number(row[11]), e.d) << row[4];
  EXPECT_DOUBLE_EQ(number(row[13]), e.min) << row[4];
  EXPECT_DOUBLE_EQ(number(row[14]), e.max) << row[4];
  // The scatter: Sigma, and the model weight with its variable written as x.
  EXPECT_DOUBLE_EQ(number(row[15]), e.sigma) << row[4];
  const std::string weight = std::regex_replace(row[6], std::regex("dbh|age"), "x");
  Weight w{};
  ASSERT_TRUE(parse_weight(weight, w)) << row[6];
  EXPECT_EQ(w, e.weight) << row[4];
}

TEST(Allometry, ModestoEquationsAreTheDatabasesRows) {
  const auto rows = modesto_rows();
  const Allometry a = modesto_london_plane();
  ASSERT_TRUE(rows.count("dbh") && rows.count("tree ht") && rows.count("crown dia") &&
              rows.count("crown ht") && rows.count("leaf area"));
  EXPECT_EQ(rows.at("dbh")[3], "age");
  expect_row(rows.at("dbh"), a.dbh);
  expect_row(rows.at("tree ht"), a.height);
  expect_row(rows.at("crown dia"), a.crown_diameter);
  expect_row(rows.at("crown ht"), a.crown_height);
  expect_row(rows.at("leaf area"), a.leaf_area);
  // The species file carries the same rows.
  const auto file = std::get<Parameters>(
      load_species(testing::source_file("data/species/london_plane.toml")).parameters);
  expect_row(rows.at("dbh"), file.allometry.dbh);
  expect_row(rows.at("tree ht"), file.allometry.height);
  expect_row(rows.at("crown dia"), file.allometry.crown_diameter);
  expect_row(rows.at("crown ht"), file.allometry.crown_height);
  expect_row(rows.at("leaf area"), file.allometry.leaf_area);
}

TEST(Allometry, ModestoAtTwentyYearsAsTheDataReadmeGivesIt) {
  // data README: age 20 -> dbh 40.6 cm, height 15.0 m, crown diameter 12.5 m.
  const Allometry a = modesto_london_plane();
  EXPECT_NEAR(a.f_dbh(20), 40.6, 0.05);
  EXPECT_NEAR(a.f_height(20), 15.0, 0.05);
  EXPECT_NEAR(a.f_crown_diameter(20), 12.5, 0.05);
}

TEST(Allometry, LogLogFormAndClamping) {
  Equation e;
  e.form = ModelForm::loglogw1;
  e.a = -0.32476, e.b = 2.07239, e.c = 0.05105;
  e.min = 1.34, e.max = 13.19;
  const double x = 40.0;
  EXPECT_DOUBLE_EQ(e(x), std::exp(-0.32476 + 2.07239 * std::log(std::log(41.0) + 0.05105 / 2)));
  EXPECT_DOUBLE_EQ(e(1e6), 13.19);  // clamped to the predicted range
  EXPECT_DOUBLE_EQ(e(0.0), 1.34);
  const Allometry a = modesto_london_plane();
  // DBH stops at 55.57 cm; the data README: "valid to 55.6 cm (age ~65)".
  EXPECT_NEAR(a.max_age, 65.0, 1.5);
  EXPECT_DOUBLE_EQ(a.f_dbh(a.max_age + 20), 55.57);
  // Every function grows with age up to the end of the range.
  for (double t = 1; t <= a.max_age; t += 1) {
    EXPECT_GE(a.f_dbh(t), a.f_dbh(t - 1));
    EXPECT_GE(a.f_height(t), a.f_height(t - 1));
    EXPECT_GE(a.f_crown_diameter(t), a.f_crown_diameter(t - 1));
    EXPECT_GE(a.f_crown_height(t), a.f_crown_height(t - 1));
    EXPECT_GE(a.f_leaf_area(t), a.f_leaf_area(t - 1));
  }
}

}  // namespace
}  // namespace landsim::trees::measured_growth
