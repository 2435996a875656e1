#pragma once
// `landsim export-obj [SCENARIO] --out FILE.obj [--max-trees N]`
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace landsim::app {

struct ExportObjArgs {
  std::vector<std::string> sets;  // --set key=value overrides
  std::string scenario;
  std::string out;
  std::string view;                      // empty: the first
  std::optional<std::size_t> max_trees;  // empty: every tree
  bool flatten = false;
  std::string frame = "terrain";
  bool print_pathtracer = false;
};

CLI::App* add_export_obj_command(CLI::App& app, ExportObjArgs& args);
int run_export_obj(const ExportObjArgs& args);

}  // namespace landsim::app
