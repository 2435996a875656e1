#pragma once
// Oriented boxes for aerial views (docs/OUTPUTS.md "Annotations"): DOTA's labelTxt (four
// corners clockwise from the head, category, difficult; gsd for orthographic views) and
// Ultralytics' YOLO-OBB labels (class, four corners normalised by the image size). Each box is
// the least rectangle around the object's target pixels (its footprint's with amodal).
#include <filesystem>

#include "exporters/annotations.h"
#include "exporters/detail/annotation_set.h"

namespace landsim::exporters::detail {

void write_dota(const json& manifest, const std::filesystem::path& set,
                const std::filesystem::path& out, const AnnotationOptions& options,
                AnnotationSummary& summary);

void write_yolo_obb(const json& manifest, const std::filesystem::path& set,
                    const std::filesystem::path& out, const AnnotationOptions& options,
                    AnnotationSummary& summary);

}  // namespace landsim::exporters::detail
