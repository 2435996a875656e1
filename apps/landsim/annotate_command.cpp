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
      "Write COCO, KITTI, YOLO, YOLO-OBB, DOTA or Pascal VOC annotations of an image set's "
      "scene objects (docs/OUTPUTS.md)");
  cmd->add_option("set", args.set, "An image set written by landsim render")->required();
  cmd->add_option("--format", args.formats,
                  "coco, kitti, yolo, yolo-obb, dota or voc; several comma-separated "
                  "(coco,kitti,yolo)")
      ->delimiter(',')
      ->check(CLI::IsMember({"coco", "kitti", "yolo", "yolo-obb", "dota", "voc"}))
      ->capture_default_str();
  cmd->add_option("--out", args.out,
                  "Where to write them (default: SET/<format>; with several formats OUT/<format>)");
  cmd->add_option("--image", args.image,
                  "COCO's file_name, VOC's filename: the preview PNG, the EXR, or the sensor's "
                  "digital numbers")
      ->check(CLI::IsMember({"preview", "exr", "dn"}))
      ->capture_default_str();
  cmd->add_flag("--amodal", args.amodal,
                "YOLO, YOLO-OBB, DOTA, VOC: boxes of the unoccluded footprint, not the visible "
                "pixels (COCO has both)");
  cmd->add_option("--min-pixels", args.min_pixels,
                  "Leave out objects with fewer visible pixels (any coverage counts)")
      ->check(CLI::Range(1, 1 << 30))
      ->capture_default_str();
  cmd->add_flag("--trees", args.trees,
                "All but KITTI: each tree too (the instance layer), its species its category");
  cmd->add_flag("--json", args.json, "Print what was written as one JSON object on stdout");
  return cmd;
}

namespace {
exporters::AnnotationFormat format_named(const std::string& name) {
  using exporters::AnnotationFormat;
  if (name == "kitti") return AnnotationFormat::kitti;
  if (name == "yolo") return AnnotationFormat::yolo;
  if (name == "yolo-obb") return AnnotationFormat::yolo_obb;
  if (name == "dota") return AnnotationFormat::dota;
  if (name == "voc") return AnnotationFormat::voc;
  return AnnotationFormat::coco;
}
}  // namespace

int run_annotate(const AnnotateArgs& args) {
  exporters::AnnotationOptions o;
  o.min_pixels = args.min_pixels;
  o.trees = args.trees;
  o.amodal = args.amodal;
  o.image = args.image == "exr"  ? exporters::AnnotationOptions::Image::exr
            : args.image == "dn" ? exporters::AnnotationOptions::Image::dn
                                 : exporters::AnnotationOptions::Image::preview;
  nlohmann::json formats = nlohmann::json::array();
  exporters::AnnotationSummary total;
  std::string first_out;
  for (const std::string& format : args.formats) {
    o.format = format_named(format);
    const std::string out = args.out.empty()          ? args.set + "/" + format
                            : args.formats.size() > 1 ? args.out + "/" + format
                                                      : args.out;
    const exporters::AnnotationSummary s = exporters::write_annotations(args.set, out, o);
    if (first_out.empty()) first_out = out;
    total.images = s.images;
    total.objects = std::max(total.objects, s.objects);
    formats.push_back({{"format", format}, {"out", out}, {"objects", s.objects}});
    if (!args.json)
      std::cout << fmt::format("{}: {} annotations in {} images ({})\n", out, s.objects, s.images,
                               format);
  }
  if (args.json)
    std::cout << nlohmann::json{{"out", first_out},
                                {"images", total.images},
                                {"objects", total.objects},
                                {"formats", formats}}
                     .dump()
              << "\n";
  return 0;
}

}  // namespace landsim::app
