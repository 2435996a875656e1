#include "exporters/detail/oriented_annotations.h"

#include <fmt/format.h>

#include <cmath>

#include "exporters/oriented_box.h"
#include "renderer/output/image_output.h"

namespace landsim::exporters::detail {
namespace {

// One oriented annotation: its class, box and whether DOTA calls it difficult.
struct OrientedItem {
  std::string name;
  OrientedBox box;
  bool difficult = false;
};

// Where an object's front points in the image: the derivative of the projection of its centre
// moved along its front (the box's second axis in the camera's OpenCV frame). Orthographic
// views move it as it moves; the others divide by depth. None for spherical views or a front
// that points along the ray.
std::optional<ImagePoint> head_in_image(const json& object, const json& camera) {
  const json& box = object.at("box3d");
  const json& r = box.at("rotation_camera");
  const double fx = r.at(0).at(1), fy = r.at(1).at(1), fz = r.at(2).at(1);
  const auto c = box.at("centre_camera").get<std::vector<double>>();
  ImagePoint h{fx, fy};  // orthographic: the front's own image motion
  double scale = 1.0;    // the size of h for a front across the view
  if (camera.at("projection") != "orthographic") {
    if (!camera.contains("K") || c.at(2) <= 0.0) return std::nullopt;
    const double kx = camera.at("K").at(0).at(0), ky = camera.at("K").at(1).at(1);
    h = {kx * (fx * c.at(2) - c.at(0) * fz), ky * (fy * c.at(2) - c.at(1) * fz)};
    scale = kx * c.at(2);
  }
  const double length = std::hypot(h.x, h.y);
  if (length < 1e-6 * scale) return std::nullopt;
  return ImagePoint{h.x / length, h.y / length};
}

// The image's annotated objects (and trees) as oriented boxes.
std::vector<OrientedItem> oriented_items(const json& manifest, const std::filesystem::path& set,
                                         const json& image, const AnnotationOptions& options) {
  const auto names = classes(manifest.at("legend"));
  const renderer::Film film = renderer::read_exr(set / image.at("path").get<std::string>());
  std::vector<OrientedItem> out;
  for (const json& o : image.value("objects", json::array())) {
    if (!annotated(o, options)) continue;
    const auto mask = options.amodal ? footprint_mask(o, film.width(), film.height())
                                     : target_mask(film, o.at("target").get<std::uint32_t>());
    const auto box = oriented_extent(mask, film.width(), film.height());
    if (!box) continue;
    out.push_back({class_of(o, names), clockwise_from(*box, head_in_image(o, image.at("camera"))),
                   occlusion_level(o.at("visible_fraction").get<double>()) == 2});
  }
  if (options.trees)
    for (const auto& [id, t] : trees_in(film)) {
      if (t.pixels < options.min_pixels) continue;
      const auto box = oriented_extent(instance_mask(film, id), film.width(), film.height());
      if (box) out.push_back({species_name(manifest.at("legend"), t.species), *box, false});
    }
  return out;
}

// DOTA splits a line at spaces: a class's spaces become hyphens (DOTA's "large-vehicle").
std::string dota_category(std::string name) {
  for (char& c : name)
    if (std::isspace(static_cast<unsigned char>(c))) c = '-';
  return name;
}

// DOTA's ground sample distance: metres a pixel for an orthographic view, else unknown.
std::string dota_gsd(const json& camera) {
  if (camera.at("projection") != "orthographic") return "null";
  return fmt::format("{:.9g}",
                     camera.at("extent_m").at(0).get<double>() / camera.at("width").get<double>());
}

}  // namespace

void write_dota(const json& manifest, const std::filesystem::path& set,
                const std::filesystem::path& out, const AnnotationOptions& options,
                AnnotationSummary& summary) {
  std::filesystem::create_directories(out / "labelTxt");
  for (const json& image : manifest.at("images")) {
    std::string text = "imagesource:landsim\ngsd:" + dota_gsd(image.at("camera")) + "\n";
    for (const OrientedItem& item : oriented_items(manifest, set, image, options)) {
      for (const ImagePoint& p : item.box.corners) text += fmt::format("{:.2f} {:.2f} ", p.x, p.y);
      text += fmt::format("{} {}\n", dota_category(item.name), item.difficult ? 1 : 0);
      ++summary.objects;
    }
    write_text(out / "labelTxt" / (stem_of(image) + ".txt"), text);
    ++summary.images;
  }
}

void write_yolo_obb(const json& manifest, const std::filesystem::path& set,
                    const std::filesystem::path& out, const AnnotationOptions& options,
                    AnnotationSummary& summary) {
  const std::map<std::string, int> index = write_yolo_classes(manifest, out, options.trees);
  std::filesystem::create_directories(out / "labels");
  for (const json& image : manifest.at("images")) {
    const double w = image.at("camera").at("width"), h = image.at("camera").at("height");
    std::string text;
    for (const OrientedItem& item : oriented_items(manifest, set, image, options)) {
      text += std::to_string(index.at(item.name));
      for (const ImagePoint& p : item.box.corners)
        text += fmt::format(" {:.6f} {:.6f}", p.x / w, p.y / h);
      text += "\n";
      ++summary.objects;
    }
    write_text(out / "labels" / (stem_of(image) + ".txt"), text);
    ++summary.images;
  }
}

}  // namespace landsim::exporters::detail
