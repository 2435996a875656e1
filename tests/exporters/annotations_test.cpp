// COCO, KITTI and YOLO annotations of a rendered set: COCO's RLE masks decode to the target
// layer exactly, KITTI's calib projects each 3D box's centre into its 2D box, YOLO lists
// every object with coverage.
#include "exporters/annotations.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <pugixml.hpp>

#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "core/input_error.h"
#include "renderer/output/image_output.h"
#include "scenes/image_set/image_set.h"
#include "tests/support/temp_dir.h"

namespace landsim::exporters {
namespace {

using landsim::testing::source_file;
using landsim::testing::TempDir;

// A car and a truck (the far one small) on the volcano's north, rendered at 8 spp.
std::filesystem::path rendered_set(const TempDir& dir) {
  const auto object = [](const std::string& name, const std::string& file, double x, double y) {
    return "[[objects]]\nname = \"" + name + "\"\nfile = \"" +
           source_file("data/objects/" + file).string() + "\"\nposition = [" + std::to_string(x) +
           ", " + std::to_string(y) + "]\nheading = 30\n";
  };
  const std::string text =
      "[terrain]\nelevation = \"" + source_file("data/terrain/volcano.asc").string() +
      "\"\n[sun]\nelevation = 40\nazimuth = 200\n[[views]]\nname = \"v\"\nposition = [300.0, "
      "640.0, 165.0]\ntarget = [300.0, 710.0, 122.0]\nfov = 30\nwidth = 96\nheight = 64\n"
      "[render]\nspp = 8\n" +
      object("car", "car.obj", 296.0, 690.0) + object("truck", "truck.obj", 310.0, 760.0);
  scenes::ImageSetOptions o;
  o.out_dir = dir / "set";
  scenes::render_image_set(scenes::parse_scenario(text, "set.toml", "."), o);
  return o.out_dir;
}

nlohmann::json load(const std::filesystem::path& p) {
  return nlohmann::json::parse(landsim::testing::read_file(p));
}

TEST(Annotations, CocoMasksAreTheTargetLayer) {
  TempDir dir;
  const auto set = rendered_set(dir);
  AnnotationOptions o;
  const AnnotationSummary s = write_annotations(set, dir / "coco", o);
  EXPECT_EQ(s.images, 1u);
  EXPECT_EQ(s.objects, 2u);
  const nlohmann::json coco = load(dir / "coco" / "annotations.json");
  ASSERT_EQ(coco["categories"].size(), 2u);
  const renderer::Film film = renderer::read_exr(set / "v.exr");
  for (const nlohmann::json& a : coco["annotations"]) {
    // Decode the column-major runs (zeros first).
    std::vector<std::uint8_t> mask;
    std::uint8_t value = 0;
    for (const auto& run : a["segmentation"]["counts"]) {
      mask.insert(mask.end(), run.get<std::size_t>(), value);
      value ^= 1;
    }
    ASSERT_EQ(mask.size(), film.pixel_count());
    const std::string name = a["landsim"]["name"];
    const std::uint32_t target = name == "car" ? 1 : 2;
    std::size_t differ = 0, area = 0;
    for (int x = 0; x < film.width(); ++x)
      for (int y = 0; y < film.height(); ++y) {
        const bool in = mask[static_cast<std::size_t>(x) * film.height() + y] != 0;
        differ += in != (film.target(x, y) == target);
        area += in;
      }
    EXPECT_EQ(differ, 0u) << name;
    EXPECT_EQ(a["area"].get<std::size_t>(), area);
    EXPECT_EQ(a["iscrowd"], 0);
  }
}

// Decodes COCO's uncompressed RLE (column-major runs, zeros first) into (x, y) extents.
struct Extent {
  int x0 = 1 << 30, y0 = 1 << 30, x1 = -1, y1 = -1;
  std::size_t pixels = 0;
};
Extent extent_of(const nlohmann::json& counts, int height) {
  Extent e;
  std::size_t at = 0;
  bool one = false;
  for (const auto& run : counts) {
    for (std::size_t k = 0; one && k < run.get<std::size_t>(); ++k) {
      const int x = static_cast<int>((at + k) / height), y = static_cast<int>((at + k) % height);
      e.x0 = std::min(e.x0, x), e.x1 = std::max(e.x1, x);
      e.y0 = std::min(e.y0, y), e.y1 = std::max(e.y1, y);
      ++e.pixels;
    }
    at += run.get<std::size_t>();
    one = !one;
  }
  return e;
}

TEST(Annotations, CocoBoxesAreTheirMasksExtentAndAmodalOnesTheFootprints) {
  TempDir dir;
  const auto set = rendered_set(dir);
  write_annotations(set, dir / "coco", AnnotationOptions{});
  const nlohmann::json coco = load(dir / "coco" / "annotations.json");
  const nlohmann::json manifest = load(set / "manifest.json");
  const int height = coco["images"][0]["height"];
  ASSERT_EQ(coco["annotations"].size(), 2u);
  for (const nlohmann::json& a : coco["annotations"]) {
    const Extent e = extent_of(a["segmentation"]["counts"], height);
    // [x, y, width, height] of the mask, to the pixel: a box one pixel narrow fails.
    EXPECT_EQ(a["bbox"], nlohmann::json({e.x0, e.y0, e.x1 - e.x0 + 1, e.y1 - e.y0 + 1}))
        << a["landsim"]["name"];
    const Extent amodal = extent_of(a["amodal_segmentation"]["counts"], height);
    EXPECT_EQ(a["amodal_bbox"], nlohmann::json({amodal.x0, amodal.y0, amodal.x1 - amodal.x0 + 1,
                                                amodal.y1 - amodal.y0 + 1}));
    EXPECT_EQ(a["amodal_area"].get<std::size_t>(), amodal.pixels);
    // The footprint holds every visible pixel.
    EXPECT_LE(amodal.x0, e.x0);
    EXPECT_LE(amodal.y0, e.y0);
    EXPECT_GE(amodal.x1, e.x1);
    EXPECT_GE(amodal.y1, e.y1);
    EXPECT_GE(amodal.pixels, e.pixels);
  }
  // The class is each object's own (its mesh), which a randomised set may change per image.
  EXPECT_EQ(manifest["images"][0]["objects"][1]["class"], "truck");
  // file_name can name the EXR; the digital numbers need a sensor.
  AnnotationOptions exr;
  exr.image = AnnotationOptions::Image::exr;
  write_annotations(set, dir / "coco_exr", exr);
  EXPECT_EQ(load(dir / "coco_exr" / "annotations.json")["images"][0]["file_name"], "v.exr");
  AnnotationOptions dn;
  dn.image = AnnotationOptions::Image::dn;
  EXPECT_THROW(write_annotations(set, dir / "coco_dn", dn), InputError);
}

TEST(Annotations, KittiCalibProjectsEachBoxCentreIntoIts2dBox) {
  TempDir dir;
  const auto set = rendered_set(dir);
  AnnotationOptions o;
  o.format = AnnotationFormat::kitti;
  write_annotations(set, dir / "kitti", o);
  // What KITTI's devkits read: P0-P3, R0_rect, Tr_velo_to_cam, Tr_imu_to_velo.
  std::map<std::string, std::vector<double>> calib;
  std::istringstream text(landsim::testing::read_file(dir / "kitti" / "calib" / "v.txt"));
  for (std::string line; std::getline(text, line);) {
    std::istringstream f(line);
    std::string tag;
    f >> tag;
    for (double v; f >> v;) calib[tag].push_back(v);
  }
  for (const char* tag : {"P0:", "P1:", "P2:", "P3:", "Tr_velo_to_cam:", "Tr_imu_to_velo:"})
    EXPECT_EQ(calib[tag].size(), 12u) << tag;
  EXPECT_EQ(calib["R0_rect:"], (std::vector<double>{1, 0, 0, 0, 1, 0, 0, 0, 1}));
  EXPECT_EQ(calib["P0:"], calib["P2:"]);  // one camera
  const std::vector<double>& p = calib["P2:"];
  std::istringstream labels(landsim::testing::read_file(dir / "kitti" / "label_2" / "v.txt"));
  int lines = 0;
  for (std::string line; std::getline(labels, line);) {
    std::istringstream f(line);
    std::string type;
    double trunc, alpha, x0, y0, x1, y1, h, w, l, x, y, z, ry;
    int occluded;
    f >> type >> trunc >> occluded >> alpha >> x0 >> y0 >> x1 >> y1 >> h >> w >> l >> x >> y >> z >>
        ry;
    ASSERT_TRUE(f) << line;
    // The box's centre: half its height above the bottom centre KITTI gives (y is down).
    const double cy = y - 0.5 * h;
    const double u = (p[0] * x + p[1] * cy + p[2] * z + p[3]) / z;
    const double v = (p[4] * x + p[5] * cy + p[6] * z + p[7]) / z;
    EXPECT_GE(u, x0 - 1.0) << line;
    EXPECT_LE(u, x1 + 1.0) << line;
    EXPECT_GE(v, y0 - 1.0) << line;
    EXPECT_LE(v, y1 + 1.0) << line;
    EXPECT_TRUE(type == "car" || type == "truck");
    ++lines;
  }
  EXPECT_EQ(lines, 2);
}

TEST(Annotations, YoloListsEveryObjectWithCoverage) {
  TempDir dir;
  const auto set = rendered_set(dir);
  AnnotationOptions o;
  o.format = AnnotationFormat::yolo;
  write_annotations(set, dir / "yolo", o);
  const nlohmann::json manifest = load(set / "manifest.json");
  std::size_t covered = 0;
  for (const auto& obj : manifest["images"][0]["objects"]) covered += obj["visible_coverage"] > 0.0;
  std::istringstream labels(landsim::testing::read_file(dir / "yolo" / "labels" / "v.txt"));
  std::size_t rows = 0;
  for (std::string line; std::getline(labels, line);) {
    int cls;
    double cx, cy, w, h;
    ASSERT_EQ(std::sscanf(line.c_str(), "%d %lf %lf %lf %lf", &cls, &cx, &cy, &w, &h), 5);
    EXPECT_TRUE(cx > 0.0 && cx < 1.0 && cy > 0.0 && cy < 1.0 && w > 0.0 && h > 0.0);
    ++rows;
  }
  EXPECT_EQ(rows, covered);
  EXPECT_EQ(landsim::testing::read_file(dir / "yolo" / "classes.txt"), "car\ntruck\n");
}

// DOTA's labelTxt read as its devkit reads it (lines of at least 9 fields: four corners,
// category, difficult; the imagesource and gsd lines skipped).
struct DotaLine {
  double x[4], y[4];
  std::string category;
  int difficult = 0;
};
std::vector<DotaLine> read_dota(const std::filesystem::path& path) {
  std::vector<DotaLine> out;
  std::istringstream text(landsim::testing::read_file(path));
  for (std::string line; std::getline(text, line);) {
    std::istringstream f(line);
    std::vector<std::string> fields;
    for (std::string w; f >> w;) fields.push_back(w);
    if (fields.size() < 9) continue;
    DotaLine d;
    for (int i = 0; i < 4; ++i)
      d.x[i] = std::stod(fields[2 * i]), d.y[i] = std::stod(fields[2 * i + 1]);
    d.category = fields[8];
    if (fields.size() > 9) d.difficult = std::stoi(fields[9]);
    out.push_back(d);
  }
  return out;
}

// Inside the quadrilateral (corners clockwise as seen, y down), with `slack` pixels.
bool inside(const DotaLine& d, double x, double y, double slack) {
  for (int i = 0; i < 4; ++i) {
    const double ex = d.x[(i + 1) % 4] - d.x[i], ey = d.y[(i + 1) % 4] - d.y[i];
    if ((ex * (y - d.y[i]) - ey * (x - d.x[i])) / std::hypot(ex, ey) < -slack) return false;
  }
  return true;
}

// Each object's oriented box holds all its target pixels, is no larger than its axis-aligned
// box, runs clockwise, and starts at the side its front faces (its box's front face centre
// projected through K); YOLO-OBB's corners are DOTA's over the image size.
TEST(Annotations, OrientedBoxesHoldTheTargetLayerFromTheHead) {
  TempDir dir;
  const auto set = rendered_set(dir);
  AnnotationOptions o;
  o.format = AnnotationFormat::dota;
  EXPECT_EQ(write_annotations(set, dir / "dota", o).objects, 2u);
  o.format = AnnotationFormat::yolo_obb;
  write_annotations(set, dir / "obb", o);
  const nlohmann::json image = load(set / "manifest.json")["images"][0];
  const renderer::Film film = renderer::read_exr(set / "v.exr");
  const std::vector<DotaLine> dota = read_dota(dir / "dota" / "labelTxt" / "v.txt");
  ASSERT_EQ(dota.size(), 2u);
  EXPECT_EQ(landsim::testing::read_file(dir / "dota" / "labelTxt" / "v.txt").substr(0, 29),
            "imagesource:landsim\ngsd:null\n");
  std::istringstream obb(landsim::testing::read_file(dir / "obb" / "labels" / "v.txt"));
  const auto& K = image["camera"]["K"];
  for (std::size_t i = 0; i < dota.size(); ++i) {
    const DotaLine& d = dota[i];
    const nlohmann::json& object = image["objects"][i];
    EXPECT_EQ(d.category, object["class"]);
    const auto target = object["target"].get<std::uint32_t>();
    for (int y = 0; y < film.height(); ++y)
      for (int x = 0; x < film.width(); ++x)
        if (film.target(x, y) == target)
          for (int c = 0; c < 4; ++c)
            ASSERT_TRUE(inside(d, x + (c & 1), y + (c >> 1), 1e-2)) << d.category << x << "," << y;
    double area2 = 0.0;
    for (int k = 0; k < 4; ++k) area2 += d.x[k] * d.y[(k + 1) % 4] - d.x[(k + 1) % 4] * d.y[k];
    EXPECT_GT(area2, 0.0);  // clockwise as seen
    const auto& b = object["bbox"];
    EXPECT_LE(0.5 * area2, (b["x1"].get<double>() - b["x0"].get<double>() + 1.0) *
                                   (b["y1"].get<double>() - b["y0"].get<double>() + 1.0) +
                               0.1);
    // The front face's centre (the box's second axis, half its length out) in the image.
    const auto& r = object["box3d"]["rotation_camera"];
    const auto c = object["box3d"]["centre_camera"].get<std::vector<double>>();
    const double half = 0.5 * object["box3d"]["size_m"][1].get<double>();
    double f[3];
    for (int k = 0; k < 3; ++k) f[k] = c[k] + half * r[k][1].get<double>();
    const double u0 = K[0][0].get<double>() * c[0] / c[2] + K[0][2].get<double>();
    const double v0 = K[1][1].get<double>() * c[1] / c[2] + K[1][2].get<double>();
    const double u1 = K[0][0].get<double>() * f[0] / f[2] + K[0][2].get<double>();
    const double v1 = K[1][1].get<double>() * f[1] / f[2] + K[1][2].get<double>();
    int facing = -1;
    double best = -1e30;
    for (int k = 0; k < 4; ++k) {
      const double mx = 0.5 * (d.x[k] + d.x[(k + 1) % 4]), my = 0.5 * (d.y[k] + d.y[(k + 1) % 4]);
      const double along = (mx - u0) * (u1 - u0) + (my - v0) * (v1 - v0);
      if (along > best) best = along, facing = k;
    }
    EXPECT_EQ(facing, 0) << d.category;
    int cls;
    double p[8];
    std::string line;
    ASSERT_TRUE(std::getline(obb, line));
    ASSERT_EQ(std::sscanf(line.c_str(), "%d %lf %lf %lf %lf %lf %lf %lf %lf", &cls, p, p + 1, p + 2,
                          p + 3, p + 4, p + 5, p + 6, p + 7),
              9);
    EXPECT_EQ(cls, static_cast<int>(i));  // classes.txt: car, truck
    for (int k = 0; k < 4; ++k) {
      EXPECT_NEAR(p[2 * k] * film.width(), d.x[k], 0.01);
      EXPECT_NEAR(p[2 * k + 1] * film.height(), d.y[k], 0.01);
    }
  }
  EXPECT_EQ(landsim::testing::read_file(dir / "obb" / "classes.txt"), "car\ntruck\n");
}

// Pascal VOC's XML as its devkit reads it: the image's size and file, each object's name and
// bndbox the target layer's extent numbered from 1, the set listed in trainval.txt.
TEST(Annotations, VocBoxesAreTheTargetLayersExtentFromOne) {
  TempDir dir;
  const auto set = rendered_set(dir);
  AnnotationOptions o;
  o.format = AnnotationFormat::voc;
  EXPECT_EQ(write_annotations(set, dir / "voc", o).objects, 2u);
  EXPECT_EQ(landsim::testing::read_file(dir / "voc" / "ImageSets" / "Main" / "trainval.txt"),
            "v\n");
  pugi::xml_document doc;
  ASSERT_TRUE(doc.load_file((dir / "voc" / "Annotations" / "v.xml").c_str()));
  const pugi::xml_node a = doc.child("annotation");
  EXPECT_STREQ(a.child_value("filename"), "v.png");
  EXPECT_EQ(a.child("size").child("width").text().as_int(), 96);
  EXPECT_EQ(a.child("size").child("height").text().as_int(), 64);
  const renderer::Film film = renderer::read_exr(set / "v.exr");
  int n = 0;
  for (const pugi::xml_node obj : a.children("object")) {
    const std::string name = obj.child_value("name");
    const std::uint32_t target = name == "car" ? 1 : 2;
    Extent e;
    for (int y = 0; y < film.height(); ++y)
      for (int x = 0; x < film.width(); ++x)
        if (film.target(x, y) == target) {
          e.x0 = std::min(e.x0, x), e.x1 = std::max(e.x1, x);
          e.y0 = std::min(e.y0, y), e.y1 = std::max(e.y1, y);
        }
    const pugi::xml_node b = obj.child("bndbox");
    EXPECT_EQ(b.child("xmin").text().as_int(), e.x0 + 1) << name;
    EXPECT_EQ(b.child("ymin").text().as_int(), e.y0 + 1) << name;
    EXPECT_EQ(b.child("xmax").text().as_int(), e.x1 + 1) << name;
    EXPECT_EQ(b.child("ymax").text().as_int(), e.y1 + 1) << name;
    EXPECT_TRUE(obj.child("difficult"));
    EXPECT_TRUE(obj.child("truncated"));
    ++n;
  }
  EXPECT_EQ(n, 2);
}

// With --trees, every tree seen is a COCO annotation of its species' category whose mask is
// its instance's pixels.
TEST(Annotations, TreesAreInstancesOfTheirSpecies) {
  TempDir dir;
  const std::string text =
      "[terrain]\nelevation = \"" + source_file("data/terrain/volcano.asc").string() +
      "\"\n[sun]\nelevation = 40\nazimuth = 200\n[[species]]\nbit = 0\nfile = \"" +
      source_file("data/species/quaking_aspen.toml").string() +
      "\"\nvariants = 1\ndensity_per_ha = 30\ncover = { rectangle = [260, 680, 340, 760] }\n"
      "[[views]]\nname = \"v\"\nposition = [300.0, 600.0, 170.0]\ntarget = [300.0, 720.0, "
      "120.0]\nfov = 40\nwidth = 96\nheight = 64\n[render]\nspp = 1\n";
  scenes::ImageSetOptions io;
  io.out_dir = dir / "set";
  scenes::render_image_set(scenes::parse_scenario(text, "set.toml", "."), io);
  AnnotationOptions o;
  o.trees = true;
  const AnnotationSummary s = write_annotations(io.out_dir, dir / "coco", o);
  const renderer::Film film = renderer::read_exr(io.out_dir / "v.exr");
  std::set<std::uint32_t> seen;
  for (int y = 0; y < film.height(); ++y)
    for (int x = 0; x < film.width(); ++x)
      if (film.instance(x, y) != renderer::kNoId) seen.insert(film.instance(x, y));
  ASSERT_GT(seen.size(), 2u);
  EXPECT_EQ(s.objects, seen.size());
  const nlohmann::json coco = load(dir / "coco" / "annotations.json");
  ASSERT_EQ(coco["categories"].size(), 1u);
  EXPECT_EQ(coco["categories"][0]["supercategory"], "tree");
  for (const nlohmann::json& a : coco["annotations"]) {
    const auto id = a["landsim"]["instance"].get<std::uint32_t>();
    std::size_t k = 0, differ = 0;
    std::uint8_t value = 0;
    for (const auto& run : a["segmentation"]["counts"]) {
      for (std::size_t n = 0; n < run.get<std::size_t>(); ++n, ++k) {
        const int x = static_cast<int>(k) / film.height(), y = static_cast<int>(k) % film.height();
        differ += (value != 0) != (film.instance(x, y) == id);
      }
      value ^= 1;
    }
    EXPECT_EQ(k, film.pixel_count());
    EXPECT_EQ(differ, 0u) << id;
  }
}

// A manifest that is not landsim's (edited, or an older version's) is refused with its name,
// never a crash: each format reads other keys.
TEST(Annotations, AnEditedManifestIsRefusedByName) {
  TempDir dir;
  const auto set = rendered_set(dir);
  nlohmann::json m = load(set / "manifest.json");
  m["images"][0]["objects"][0].erase("box3d");
  m["images"][0]["camera"].erase("width");
  m["images"][0]["objects"][1]["target"] = 7;   // not in the legend
  m["images"][0]["objects"][1].erase("class");  // so its class is looked up there
  std::ofstream(set / "manifest.json") << m.dump();
  for (const AnnotationFormat f :
       {AnnotationFormat::coco, AnnotationFormat::kitti, AnnotationFormat::yolo,
        AnnotationFormat::yolo_obb, AnnotationFormat::dota, AnnotationFormat::voc}) {
    AnnotationOptions o;
    o.format = f;
    try {
      write_annotations(set, dir / "out", o);
      ADD_FAILURE() << "an edited manifest was accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("manifest.json"), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace landsim::exporters
