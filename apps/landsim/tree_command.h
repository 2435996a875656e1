#pragma once
// `landsim tree SPECIES_FILE [--seed N] [--time T --wind S --gust G] [--quality Q]
//                            [--age YEARS] [--obj FILE] [--internodes FILE.csv] [--json]`
#include <cstdint>
#include <string>

namespace CLI {
class App;
}

namespace landsim::app {

struct TreeArgs {
  std::string species;
  std::uint64_t seed = 1;
  double time = 0.0;
  double wind = 0.0;
  double gust = 0.0;
  double quality = 1.0;
  double age = -1.0;  // years; < 0: the species file's tree
  std::string obj;
  std::string internodes;  // self-organising: the internodes, for prunings and constraints
  bool json = false;
};

CLI::App* add_tree_command(CLI::App& app, TreeArgs& args);
int run_tree(const TreeArgs& args);

}  // namespace landsim::app
