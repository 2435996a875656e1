#include "exporters/detail/voc_annotations.h"

#include <pugixml.hpp>

#include <sstream>

#include "renderer/output/image_output.h"

namespace landsim::exporters::detail {
namespace {

// VOC's flags and box for one object: its box is the visible pixels' (the footprint's with
// amodal), pixels numbered from 1 with both ends inside as the devkit counts them.
struct VocObject {
  std::string name;
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // 0-based inclusive
  bool truncated = false, occluded = false, difficult = false;
};

void add_object(pugi::xml_node annotation, const VocObject& o) {
  pugi::xml_node node = annotation.append_child("object");
  node.append_child("name").text().set(o.name.c_str());
  node.append_child("pose").text().set("Unspecified");
  node.append_child("truncated").text().set(o.truncated ? 1 : 0);
  node.append_child("occluded").text().set(o.occluded ? 1 : 0);
  node.append_child("difficult").text().set(o.difficult ? 1 : 0);
  pugi::xml_node box = node.append_child("bndbox");
  box.append_child("xmin").text().set(o.x0 + 1);
  box.append_child("ymin").text().set(o.y0 + 1);
  box.append_child("xmax").text().set(o.x1 + 1);
  box.append_child("ymax").text().set(o.y1 + 1);
}

std::vector<VocObject> voc_objects(const json& manifest, const std::filesystem::path& set,
                                   const json& image, const AnnotationOptions& options) {
  const auto names = classes(manifest.at("legend"));
  std::vector<VocObject> out;
  for (const json& o : image.value("objects", json::array())) {
    if (!annotated(o, options)) continue;
    const json& b = o.at(options.amodal ? "footprint_bbox" : "bbox");
    const int level = occlusion_level(o.at("visible_fraction").get<double>());
    const bool truncated = !o.at("truncation").is_null() && o.at("truncation").get<double>() > 0.0;
    out.push_back({class_of(o, names), b.at("x0").get<int>(), b.at("y0").get<int>(),
                   b.at("x1").get<int>(), b.at("y1").get<int>(), truncated, level >= 1,
                   level == 2});
  }
  if (options.trees)
    for (const auto& [id, t] :
         trees_in(renderer::read_exr(set / image.at("path").get<std::string>())))
      if (t.pixels >= options.min_pixels)
        out.push_back({species_name(manifest.at("legend"), t.species), t.x0, t.y0, t.x1, t.y1});
  return out;
}

std::string voc_xml(const json& manifest, const std::filesystem::path& set, const json& image,
                    const AnnotationOptions& options, AnnotationSummary& summary) {
  pugi::xml_document doc;
  pugi::xml_node a = doc.append_child("annotation");
  a.append_child("folder").text().set(set.filename().string().c_str());
  a.append_child("filename").text().set(image_file(image, set, options).get<std::string>().c_str());
  a.append_child("source").append_child("database").text().set("landsim");
  pugi::xml_node size = a.append_child("size");
  size.append_child("width").text().set(image.at("camera").at("width").get<int>());
  size.append_child("height").text().set(image.at("camera").at("height").get<int>());
  size.append_child("depth").text().set(3);
  a.append_child("segmented").text().set(0);
  for (const VocObject& o : voc_objects(manifest, set, image, options)) {
    add_object(a, o);
    ++summary.objects;
  }
  std::ostringstream text;
  doc.save(text, "  ");
  return text.str();
}

}  // namespace

void write_voc(const json& manifest, const std::filesystem::path& set,
               const std::filesystem::path& out, const AnnotationOptions& options,
               AnnotationSummary& summary) {
  std::filesystem::create_directories(out / "Annotations");
  std::filesystem::create_directories(out / "ImageSets" / "Main");
  std::string list;
  for (const json& image : manifest.at("images")) {
    write_text(out / "Annotations" / (stem_of(image) + ".xml"),
               voc_xml(manifest, set, image, options, summary));
    list += stem_of(image) + "\n";
    ++summary.images;
  }
  write_text(out / "ImageSets" / "Main" / "trainval.txt", list);
}

}  // namespace landsim::exporters::detail
