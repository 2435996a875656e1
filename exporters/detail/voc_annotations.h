#pragma once
// Pascal VOC annotations (docs/OUTPUTS.md "Annotations"): one Annotations/<image>.xml per
// image as the VOC devkit and torchvision's VOCDetection read it (size, and per object name,
// pose, truncated, occluded, difficult and a bndbox in VOC's 1-based pixel numbers), and
// ImageSets/Main/trainval.txt listing the images.
#include <filesystem>

#include "exporters/annotations.h"
#include "exporters/detail/annotation_set.h"

namespace landsim::exporters::detail {

void write_voc(const json& manifest, const std::filesystem::path& set,
               const std::filesystem::path& out, const AnnotationOptions& options,
               AnnotationSummary& summary);

}  // namespace landsim::exporters::detail
