#pragma once
// `landsim annotate SET --format coco|kitti|yolo [--out DIR] [--min-pixels N] [--trees]
//                   [--json]`:
// annotation files for machine-learning tools from an image set (docs/OUTPUTS.md).
#include <cstddef>
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace landsim::app {

struct AnnotateArgs {
  std::string set;
  std::vector<std::string> formats{"coco"};
  std::string out;                // empty: SET/<format>; several formats: OUT/<format>
  std::string image = "preview";  // COCO's file_name: preview, exr or dn
  bool amodal = false;
  std::size_t min_pixels = 1;
  bool trees = false;
  bool json = false;
};

CLI::App* add_annotate_command(CLI::App& app, AnnotateArgs& args);
int run_annotate(const AnnotateArgs& args);

}  // namespace landsim::app
