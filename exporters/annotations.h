#pragma once
// Annotations for machine-learning tools from an image set written by `landsim render`
// (docs/OUTPUTS.md "Annotations"): COCO (one JSON with categories, boxes and RLE masks from
// the target layer), KITTI (label_2 with 2D and 3D boxes, truncation and occlusion levels;
// calib with P2 from the camera's K), YOLO (normalised boxes and classes.txt), and for aerial
// views the oriented boxes of DOTA and YOLO-OBB, and Pascal VOC's XML. The objects' class is
// the stem of their mesh file (car.obj: "car").
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace landsim::exporters {

enum class AnnotationFormat { coco, kitti, yolo, yolo_obb, dota, voc };

struct AnnotationOptions {
  AnnotationFormat format = AnnotationFormat::coco;
  // Objects covering fewer visible pixels (coverage > 0) are left out.
  std::size_t min_pixels = 1;
  // Every format but KITTI: each tree (the instance layer) too, its species its category.
  bool trees = false;
  // YOLO, YOLO-OBB, DOTA, VOC: boxes of the unoccluded footprint (amodal) instead of the
  // visible pixels. (COCO carries both: `bbox` and `amodal_bbox`, `amodal_segmentation`.)
  bool amodal = false;
  // COCO's `file_name` and VOC's `filename`: the preview PNG, the EXR, or the sensor's
  // digital-number image.
  enum class Image { preview, exr, dn } image = Image::preview;
};

struct AnnotationSummary {
  std::size_t images = 0;
  std::size_t objects = 0;  // annotations written
};

// Reads `set` (its manifest.json and EXRs) and writes the annotations into `out`. Throws
// InputError naming the file for a set that is not landsim's or lacks object truth.
AnnotationSummary write_annotations(const std::filesystem::path& set,
                                    const std::filesystem::path& out,
                                    const AnnotationOptions& options);

// A binary mask (row-major, height x width) as COCO's uncompressed RLE counts: column-major
// runs, starting with a run of zeros.
std::vector<std::uint32_t> coco_rle(const std::vector<std::uint8_t>& mask, int width, int height);

}  // namespace landsim::exporters
