#pragma once
// `landsim annotate SET --format coco|kitti|yolo [--out DIR] [--min-pixels N] [--trees]
//                   [--json]`:
// annotation files for machine-learning tools from an image set (docs/OUTPUTS.md).
#include <cstddef>
#include <string>

namespace CLI {
class App;
}

namespace landsim::app {

struct AnnotateArgs {
  std::string set;
  std::string format = "coco";
  std::string out;  // empty: SET/<format>
  std::size_t min_pixels = 1;
  bool trees = false;
  bool json = false;
};

CLI::App* add_annotate_command(CLI::App& app, AnnotateArgs& args);
int run_annotate(const AnnotateArgs& args);

}  // namespace landsim::app
