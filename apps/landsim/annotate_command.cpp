#include "annotate_command.h"

#include <fmt/format.h>
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <iostream>

#include "exporters/annotations.h"

namespace landsim::app {

CLI::App* add_annotate_command(CLI::App& app, AnnotateArgs& args) {
  CLI::App* cmd = app.add_subcommand(
      "annotate",
      "Write COCO, KITTI or YOLO annotations of an image set's scene objects (docs/OUTPUTS.md)");
  cmd->add_option("set", args.set, "An image set written by landsim render")->required();
  cmd->add_option("--format", args.format, "coco, kitti or yolo")
      ->check(CLI::IsMember({"coco", "kitti", "yolo"}))
      ->capture_default_str();
  cmd->add_option("--out", args.out, "Where to write them (default: SET/<format>)");
  cmd->add_option("--min-pixels", args.min_pixels,
                  "Leave out objects with fewer visible pixels (any coverage counts)")
      ->check(CLI::Range(1, 1 << 30))
      ->capture_default_str();
  cmd->add_flag("--trees", args.trees,
                "COCO and YOLO: each tree too (the instance layer), its species its category");
  cmd->add_flag("--json", args.json, "Print what was written as one JSON object on stdout");
  return cmd;
}

int run_annotate(const AnnotateArgs& args) {
  exporters::AnnotationOptions o;
  o.format = args.format == "kitti"  ? exporters::AnnotationFormat::kitti
             : args.format == "yolo" ? exporters::AnnotationFormat::yolo
                                     : exporters::AnnotationFormat::coco;
  o.min_pixels = args.min_pixels;
  o.trees = args.trees;
  const std::string out = args.out.empty() ? args.set + "/" + args.format : args.out;
  const exporters::AnnotationSummary s = exporters::write_annotations(args.set, out, o);
  if (args.json) {
    std::cout << nlohmann::json{{"out", out}, {"images", s.images}, {"objects", s.objects}}.dump()
              << "\n";
  } else {
    std::cout << fmt::format("{}: {} annotations in {} images ({})\n", out, s.objects, s.images,
                             args.format);
  }
  return 0;
}

}  // namespace landsim::app
