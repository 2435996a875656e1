#pragma once
// The 27 London planes measured in Modesto (data/allometry/modesto_london_plane_trees.csv,
// the Urban Tree Database's raw data), for tests that check a decision against real trees.
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace landsim::trees::testing {

struct ModestoTree {
  double age, dbh_cm, height_m, crown_diameter_m;
};

inline std::vector<ModestoTree> modesto_trees() {
  std::ifstream in(std::filesystem::path(LANDSIM_SOURCE_DIR) /
                   "data/allometry/modesto_london_plane_trees.csv");
  std::vector<ModestoTree> trees;
  std::string line;
  std::getline(in, line);  // header
  while (std::getline(in, line)) {
    // The city is quoted with a comma inside: empty the quoted field first.
    const std::size_t q1 = line.find('"'), q2 = line.find('"', q1 + 1);
    line.erase(q1, q2 - q1 + 1);
    std::vector<std::string> cells;
    std::stringstream ss(line);
    for (std::string c; std::getline(ss, c, ',');) cells.push_back(c);
    // Region, (the city), SpCode, name, Age, DBH, TreeHt, CrnBase, CrnHt, CdiaPar, CDiaPerp,
    // AvgCdia, Leaf.
    trees.push_back(
        {std::stod(cells[4]), std::stod(cells[5]), std::stod(cells[6]), std::stod(cells[11])});
  }
  return trees;
}

}  // namespace landsim::trees::testing
