#include "exporters/annotations.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <map>
#include <stdexcept>

#include "core/atomic_file.h"
#include "core/input_error.h"
#include "renderer/output/image_output.h"
#include "scenes/image_set/image_set.h"

namespace landsim::exporters {
namespace {

using nlohmann::json;

// The set's manifest, which must carry the legend annotations name their classes from.
json read_annotated_manifest(const std::filesystem::path& set) {
  json j = scenes::read_manifest(set);
  if (!j.contains("legend"))
    throw InputError((set / "manifest.json").string() +
                     ": a landsim manifest without a legend (render the set again with this "
                     "version)");
  return j;
}

// A tree in an image: its instance id's pixels (first samples), their box and its species.
struct TreeSeen {
  std::uint32_t species = 0;
  std::size_t pixels = 0;
  int x0 = 1 << 30, y0 = 1 << 30, x1 = -1, y1 = -1;
};
std::map<std::uint32_t, TreeSeen> trees_in(const renderer::Film& film) {
  std::map<std::uint32_t, TreeSeen> out;
  for (int y = 0; y < film.height(); ++y)
    for (int x = 0; x < film.width(); ++x) {
      const std::uint32_t id = film.instance(x, y);
      if (id == renderer::kNoId) continue;
      TreeSeen& t = out[id];
      t.species = film.species(x, y);
      ++t.pixels;
      t.x0 = std::min(t.x0, x), t.y0 = std::min(t.y0, y);
      t.x1 = std::max(t.x1, x), t.y1 = std::max(t.y1, y);
    }
  return out;
}

std::string species_name(const json& legend, std::uint32_t species) {
  return legend.at("species").at("values").at(species).at("name").get<std::string>();
}

// The class of each target id: its mesh file's stem.
std::map<std::uint32_t, std::string> classes(const json& legend) {
  std::map<std::uint32_t, std::string> out;
  for (const json& v : legend.at("target").at("values"))
    out[v.at("id").get<std::uint32_t>()] =
        std::filesystem::path(v.at("file").get<std::string>()).stem().string();
  return out;
}

// The classes of a set, each once, in order: the objects' (their mesh stems), then with
// trees the species'.
struct ClassName {
  std::string name;
  const char* supercategory;
};
std::vector<ClassName> class_names(const json& m,
                                   const std::map<std::uint32_t, std::string>& objects,
                                   bool trees) {
  std::vector<ClassName> out;
  const auto add = [&](const std::string& name, const char* super) {
    for (const ClassName& c : out)
      if (c.name == name) return;
    out.push_back({name, super});
  };
  for (const auto& [id, name] : objects) add(name, "object");
  for (const json& image : m.at("images"))  // classes drawn per image ([randomise])
    for (const json& o : image.value("objects", json::array()))
      if (o.contains("class")) add(o.at("class").get<std::string>(), "object");
  if (trees)
    for (const json& sp : m.at("legend").at("species").at("values"))
      add(sp.at("name").get<std::string>(), "tree");
  return out;
}

void write_text(const std::filesystem::path& path, const std::string& text) {
  AtomicFile out(path);
  {
    std::ofstream f(out.temp_path(), std::ios::binary);
    f << text;
    if (!f) throw std::runtime_error("cannot write " + path.string());
  }
  out.commit();
}

// An object's class: its truth's (the mesh it was drawn with in that image), or the legend's
// for sets rendered before objects carried one.
std::string class_of(const json& o, const std::map<std::uint32_t, std::string>& legend) {
  if (o.contains("class")) return o.at("class").get<std::string>();
  return legend.at(o.at("target").get<std::uint32_t>());
}

// An object of an image worth annotating: in the manifest's truth with enough pixels.
bool annotated(const json& o, const AnnotationOptions& options) {
  return !o.at("bbox").is_null() && o.at("visible_pixels").get<std::size_t>() >= options.min_pixels;
}

std::string stem_of(const json& image) {
  return std::filesystem::path(image.at("path").get<std::string>()).stem().string();
}

// KITTI's occlusion level from the visible fraction: 0 fully visible, 1 partly, 2 largely.
int occlusion_level(double visible_fraction) {
  return visible_fraction >= 0.9 ? 0 : visible_fraction >= 0.5 ? 1 : 2;
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
  std::map<std::string, int> index;
  std::string list;
  for (const ClassName& c : class_names(m, names, options.trees)) {
    index.emplace(c.name, static_cast<int>(index.size()));
    list += c.name + "\n";
  }
  std::filesystem::create_directories(out / "labels");
  write_text(out / "classes.txt", list);
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

// The image COCO's file_name names: the preview, the EXR, or the digital-number image.
json image_file(const json& image, const std::filesystem::path& set,
                const AnnotationOptions& options) {
  if (options.image == AnnotationOptions::Image::exr) return image.at("path");
  if (options.image == AnnotationOptions::Image::preview) return image.at("preview");
  if (!image.contains("sensor") || !image.at("sensor").contains("path"))
    throw InputError((set / "manifest.json").string() + ": image " +
                     image.at("path").get<std::string>() +
                     " has no digital-number image (render the set with a [sensor])");
  return image.at("sensor").at("path");
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
      const auto target = o.at("target").get<std::uint32_t>();
      std::vector<std::uint8_t> mask(film.pixel_count());
      std::size_t area = 0;
      for (int y = 0; y < film.height(); ++y)
        for (int x = 0; x < film.width(); ++x)
          if (film.target(x, y) == target) {
            mask[static_cast<std::size_t>(y) * film.width() + x] = 1;
            ++area;
          }
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
        std::vector<std::uint8_t> mask(film.pixel_count());
        for (int y = t.y0; y <= t.y1; ++y)
          for (int x = t.x0; x <= t.x1; ++x)
            mask[static_cast<std::size_t>(y) * film.width() + x] = film.instance(x, y) == id;
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
    }
  } catch (const json::exception& e) {
    // A key missing or of another type: an edited manifest, or one of an older version.
    throw InputError((set / "manifest.json").string() +
                     ": not the manifest landsim writes (render the set again with this "
                     "version): " +
                     e.what());
  } catch (const std::out_of_range& e) {
    throw InputError((set / "manifest.json").string() +
                     ": an id its legend does not name: " + e.what());
  }
  return summary;
}

}  // namespace landsim::exporters
