#pragma once
// What every annotation format reads from an image set (docs/OUTPUTS.md "Annotations"): the
// classes (objects by mesh stem, trees by species), which objects are annotated, the masks of
// an object's visible pixels, its footprint and a tree's instance, and atomic text files.
#include <nlohmann/json.hpp>

#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "exporters/annotations.h"
#include "renderer/output/film.h"

namespace landsim::exporters::detail {

using nlohmann::json;

// A tree in an image: its instance id's pixels (first samples), their box and its species.
struct TreeSeen {
  std::uint32_t species = 0;
  std::size_t pixels = 0;
  int x0 = 1 << 30, y0 = 1 << 30, x1 = -1, y1 = -1;
};
std::map<std::uint32_t, TreeSeen> trees_in(const renderer::Film& film);
std::string species_name(const json& legend, std::uint32_t species);

// The class of each target id: its mesh file's stem.
std::map<std::uint32_t, std::string> classes(const json& legend);

// The classes of a set, each once, in order: the objects' (their mesh stems), then with
// trees the species'.
struct ClassName {
  std::string name;
  const char* supercategory;
};
std::vector<ClassName> class_names(const json& manifest,
                                   const std::map<std::uint32_t, std::string>& objects, bool trees);

// An object's class: its truth's (the mesh it was drawn with in that image), or the legend's
// for sets rendered before objects carried one.
std::string class_of(const json& object, const std::map<std::uint32_t, std::string>& legend);

// An object of an image worth annotating: in the manifest's truth with enough pixels.
bool annotated(const json& object, const AnnotationOptions& options);

// KITTI's occlusion level from the visible fraction: 0 fully visible, 1 partly, 2 largely.
int occlusion_level(double visible_fraction);

std::string stem_of(const json& image);

// The image a format's file name names: the preview, the EXR, or the digital-number image.
json image_file(const json& image, const std::filesystem::path& set,
                const AnnotationOptions& options);

// Masks (row-major, width x height, 1 inside): the pixels whose target is `target`; an
// object's unoccluded footprint (its manifest RLE); the pixels of tree `instance`.
std::vector<std::uint8_t> target_mask(const renderer::Film& film, std::uint32_t target);
std::vector<std::uint8_t> footprint_mask(const json& object, int width, int height);
std::vector<std::uint8_t> instance_mask(const renderer::Film& film, std::uint32_t instance);

// YOLO's classes.txt (each class of class_names on a line) written into `out`, and each
// class's index in it, as YOLO and YOLO-OBB labels give a class.
std::map<std::string, int> write_yolo_classes(const json& manifest,
                                              const std::filesystem::path& out, bool trees);

void write_text(const std::filesystem::path& path, const std::string& text);

}  // namespace landsim::exporters::detail
