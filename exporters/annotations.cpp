#include "exporters/annotations.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

#include "core/input_error.h"
#include "exporters/detail/annotation_set.h"
#include "exporters/detail/oriented_annotations.h"
#include "exporters/detail/voc_annotations.h"
#include "renderer/output/image_output.h"
#include "scenes/image_set/image_set.h"

namespace landsim::exporters {
namespace {

using nlohmann::json;
using namespace detail;

// The set's manifest, which must carry the legend annotations name their classes from.
json read_annotated_manifest(const std::filesystem::path& set) {
  json j = scenes::read_manifest(set);
  if (!j.contains("legend"))
    throw InputError((set / "manifest.json").string() +
                     ": a landsim manifest without a legend (render the set again with this "
                     "version)");
  return j;
}

std::string kitti_line(const json& o, const std::string& type) {
  const json& b = o.at("bbox");
  const json& box = o.at("box3d");
  const auto m = box.at("rotation_camera");
  const auto size = box.at("size_m").get<std::vector<double>>();  // right, front, up
  const auto c = box.at("centre_camera").get<std::vector<double>>();
  // The box's front and up in the camera frame (columns 1 and 2 of rotation_camera).
  const double fx = m.at(0).at(1).get<double>(), fz = m.at(2).at(1).get<double>();
  const double ux = m.at(0).at(2).get<double>(), uy = m.at(1).at(2).get<double>(),
               uz = m.at(2).at(2).get<double>();
  const double ry = std::atan2(-fz, fx);  // KITTI: the front is (cos ry, 0, -sin ry)
  // KITTI locates a box by its bottom centre.
  const double h = size.at(2);
  const double x = c.at(0) - 0.5 * h * ux, y = c.at(1) - 0.5 * h * uy, z = c.at(2) - 0.5 * h * uz;
  const double alpha = ry - std::atan2(x, z);
  const double truncation = o.at("truncation").is_null() ? 0.0 : o.at("truncation").get<double>();
  return fmt::format(
      "{} {:.3f} {} {:.3f} {} {} {} {} {:.3f} {:.3f} {:.3f} {:.3f} {:.3f} {:.3f} {:.3f}\n", type,
      truncation, occlusion_level(o.at("visible_fraction").get<double>()),
      std::remainder(alpha, 2.0 * M_PI), b.at("x0").get<int>(), b.at("y0").get<int>(),
      b.at("x1").get<int>() + 1, b.at("y1").get<int>() + 1, h, size.at(0), size.at(1), x, y, z, ry);
}

// KITTI's calib file as its devkits read it: P0-P3 (one camera, so all four are K [I | 0]),
// R0_rect the identity (the image is already rectified), and Tr_velo_to_cam, Tr_imu_to_velo
// the identity: a scene has no lidar or IMU, and the labels' 3D boxes are in the camera frame.
std::string kitti_calib(const json& camera) {
  const json& k = camera.at("K");
  std::string p;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) p += fmt::format(" {:.9g}", k.at(r).at(c).get<double>());
    p += " 0";
  }
  const std::string identity34 = " 1 0 0 0 0 1 0 0 0 0 1 0";
  return "P0:" + p + "\nP1:" + p + "\nP2:" + p + "\nP3:" + p +
         "\nR0_rect: 1 0 0 0 1 0 0 0 1\nTr_velo_to_cam:" + identity34 +
         "\nTr_imu_to_velo:" + identity34 + "\n";
}

void write_kitti(const json& m, const std::filesystem::path& set, const std::filesystem::path& out,
                 const AnnotationOptions& options, AnnotationSummary& summary) {
  const auto names = classes(m.at("legend"));
  std::filesystem::create_directories(out / "label_2");
  std::filesystem::create_directories(out / "calib");
  for (const json& image : m.at("images")) {
    if (!image.at("camera").contains("K") || image.at("camera").at("projection") != "perspective")
      throw InputError((set / "manifest.json").string() + ": image " +
                       image.at("path").get<std::string>() +
                       ": KITTI needs perspective views (its calib is a pinhole's P2)");
    std::string labels;
    for (const json& o : image.value("objects", json::array()))
      if (annotated(o, options)) {
        labels += kitti_line(o, class_of(o, names));
        ++summary.objects;
      }
    write_text(out / "label_2" / (stem_of(image) + ".txt"), labels);
    write_text(out / "calib" / (stem_of(image) + ".txt"), kitti_calib(image.at("camera")));
    ++summary.images;
  }
}

void write_yolo(const json& m, const std::filesystem::path& set, const std::filesystem::path& out,
                const AnnotationOptions& options, AnnotationSummary& summary) {
  const auto names = classes(m.at("legend"));
  const std::map<std::string, int> index = write_yolo_classes(m, out, options.trees);
  std::filesystem::create_directories(out / "labels");
  for (const json& image : m.at("images")) {
    const double w = image.at("camera").at("width").get<double>(),
                 h = image.at("camera").at("height").get<double>();
    std::string labels;
    for (const json& o : image.value("objects", json::array())) {
      if (!annotated(o, options)) continue;
      const json& b = o.at(options.amodal ? "footprint_bbox" : "bbox");
      const double x0 = b.at("x0").get<double>(), y0 = b.at("y0").get<double>();
      const double x1 = b.at("x1").get<double>() + 1.0, y1 = b.at("y1").get<double>() + 1.0;
      labels += fmt::format("{} {:.6f} {:.6f} {:.6f} {:.6f}\n", index.at(class_of(o, names)),
                            0.5 * (x0 + x1) / w, 0.5 * (y0 + y1) / h, (x1 - x0) / w, (y1 - y0) / h);
      ++summary.objects;
    }
    if (options.trees)
      for (const auto& [id, t] :
           trees_in(renderer::read_exr(set / image.at("path").get<std::string>()))) {
        if (t.pixels < options.min_pixels) continue;
        const double x0 = t.x0, y0 = t.y0, x1 = t.x1 + 1.0, y1 = t.y1 + 1.0;
        labels += fmt::format(
            "{} {:.6f} {:.6f} {:.6f} {:.6f}\n", index.at(species_name(m.at("legend"), t.species)),
            0.5 * (x0 + x1) / w, 0.5 * (y0 + y1) / h, (x1 - x0) / w, (y1 - y0) / h);
        ++summary.objects;
      }
    write_text(out / "labels" / (stem_of(image) + ".txt"), labels);
    ++summary.images;
  }
}

// A manifest box {x0, y0, x1, y1} (inclusive pixels) as COCO's [x, y, width, height].
json coco_box(const json& b) {
  if (b.is_null()) return nullptr;
  const int x0 = b.at("x0"), y0 = b.at("y0"), x1 = b.at("x1"), y1 = b.at("y1");
  return {x0, y0, x1 - x0 + 1, y1 - y0 + 1};
}

void write_coco(const json& m, const std::filesystem::path& set, const std::filesystem::path& out,
                const AnnotationOptions& options, AnnotationSummary& summary) {
  const auto names = classes(m.at("legend"));
  std::map<std::string, int> category;
  json categories = json::array();
  for (const ClassName& c : class_names(m, names, options.trees)) {
    category.emplace(c.name, static_cast<int>(category.size()) + 1);
    categories.push_back(
        {{"id", category.at(c.name)}, {"name", c.name}, {"supercategory", c.supercategory}});
  }
  json images = json::array(), annotations = json::array();
  for (const json& image : m.at("images")) {
    const renderer::Film film = renderer::read_exr(set / image.at("path").get<std::string>());
    const int image_id = static_cast<int>(images.size()) + 1;
    images.push_back({{"id", image_id},
                      {"file_name", image_file(image, set, options)},
                      {"exr", image.at("path")},
                      {"width", film.width()},
                      {"height", film.height()}});
    for (const json& o : image.value("objects", json::array())) {
      if (!annotated(o, options)) continue;
      const auto mask = target_mask(film, o.at("target").get<std::uint32_t>());
      const auto area = static_cast<std::size_t>(std::count(mask.begin(), mask.end(), 1));
      annotations.push_back({{"id", annotations.size() + 1},
                             {"image_id", image_id},
                             {"category_id", category.at(class_of(o, names))},
                             {"bbox", coco_box(o.at("bbox"))},
                             {"area", area},
                             {"iscrowd", 0},
                             {"segmentation",
                              {{"size", {film.height(), film.width()}},
                               {"counts", coco_rle(mask, film.width(), film.height())}}},
                             {"amodal_bbox", coco_box(o.at("footprint_bbox"))},
                             {"amodal_area", o.at("footprint_pixels")},
                             {"amodal_segmentation",
                              {{"size", {film.height(), film.width()}},
                               {"counts", o.value("footprint_mask", json::array())}}},
                             {"landsim",
                              {{"name", o.at("name")},
                               {"visible_coverage", o.at("visible_coverage")},
                               {"visible_fraction", o.at("visible_fraction")},
                               {"truncation", o.at("truncation")}}}});
      ++summary.objects;
    }
    if (options.trees)
      for (const auto& [id, t] : trees_in(film)) {
        if (t.pixels < options.min_pixels) continue;
        const auto mask = instance_mask(film, id);
        annotations.push_back(
            {{"id", annotations.size() + 1},
             {"image_id", image_id},
             {"category_id", category.at(species_name(m.at("legend"), t.species))},
             {"bbox", {t.x0, t.y0, t.x1 - t.x0 + 1, t.y1 - t.y0 + 1}},
             {"area", t.pixels},
             {"iscrowd", 0},
             {"segmentation",
              {{"size", {film.height(), film.width()}},
               {"counts", coco_rle(mask, film.width(), film.height())}}},
             {"landsim", {{"instance", id}}}});
        ++summary.objects;
      }
    ++summary.images;
  }
  const json coco = {{"info", {{"description", "landsim image set " + set.string()}}},
                     {"images", images},
                     {"annotations", annotations},
                     {"categories", categories}};
  std::filesystem::create_directories(out);
  write_text(out / "annotations.json", coco.dump() + "\n");
}

}  // namespace

std::vector<std::uint32_t> coco_rle(const std::vector<std::uint8_t>& mask, int width, int height) {
  std::vector<std::uint32_t> counts;
  std::uint8_t current = 0;
  std::uint32_t run = 0;
  for (int x = 0; x < width; ++x)
    for (int y = 0; y < height; ++y) {
      const std::uint8_t v = mask[static_cast<std::size_t>(y) * width + x] != 0 ? 1 : 0;
      if (v != current) {
        counts.push_back(run);
        run = 0;
        current = v;
      }
      ++run;
    }
  counts.push_back(run);
  return counts;
}

AnnotationSummary write_annotations(const std::filesystem::path& set,
                                    const std::filesystem::path& out,
                                    const AnnotationOptions& options) {
  const json m = read_annotated_manifest(set);
  AnnotationSummary summary;
  try {
    switch (options.format) {
      case AnnotationFormat::coco:
        write_coco(m, set, out, options, summary);
        break;
      case AnnotationFormat::kitti:
        write_kitti(m, set, out, options, summary);
        break;
      case AnnotationFormat::yolo:
        write_yolo(m, set, out, options, summary);
        break;
      case AnnotationFormat::yolo_obb:
        write_yolo_obb(m, set, out, options, summary);
        break;
      case AnnotationFormat::dota:
        write_dota(m, set, out, options, summary);
        break;
      case AnnotationFormat::voc:
        write_voc(m, set, out, options, summary);
        break;
    }
  } catch (const json::exception& e) {
    // A key missing or of another type: an edited manifest, or one of an older version.
    throw InputError((set / "manifest.json").string() +
                     ": not the manifest landsim writes (render the set again with this "
                     "version): " +
                     e.what());
  } catch (const std::out_of_range& e) {
    throw InputError(
        (set / "manifest.json").string() +
        ": an id its legend does not name, or a mask larger than its image: " + e.what());
  }
  return summary;
}

}  // namespace landsim::exporters
