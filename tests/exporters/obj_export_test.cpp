// The scene OBJ carries the scene objects in place, in terrain coordinates.
#include "exporters/obj_export.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "renderer/camera.h"
#include "renderer/transport/render.h"
#include "scenes/builder/scene_builder.h"
#include "tests/support/temp_dir.h"

namespace landsim::exporters {
namespace {

using landsim::testing::source_file;
using landsim::testing::TempDir;

TEST(SceneObj, ObjectsAreWrittenInPlaceAsGroupsOfTheirOwn) {
  TempDir dir;
  const auto file = dir.write(
      "s.toml", "[terrain]\nelevation = \"" + source_file("data/terrain/volcano.asc").string() +
                    "\"\n[sun]\nelevation = 40\nazimuth = 200\n[[views]]\nname = \"v\"\n"
                    "position = [300.0, 300.0, 400.0]\ntarget = [320.0, 320.0, 200.0]\n"
                    "[[objects]]\nname = \"red car\"\nfile = \"" +
                    source_file("data/objects/car.obj").string() +
                    "\"\nposition = [300.0, 400.0]\nheading = 30\n");
  const renderer::Scene scene = scenes::build_scene(scenes::load_scenario(file));
  const SceneObjSummary s = write_scene_obj(scene, dir / "scene.obj", {});
  const renderer::ObjectPrototype& p = scene.object_prototypes[0];
  EXPECT_EQ(s.object_triangles, p.triangle_count());
  std::ifstream in(dir / "scene.obj");
  std::string line;
  bool inside = false;
  std::vector<Vec3> vertices;
  while (std::getline(in, line)) {
    if (line.rfind("g ", 0) == 0) inside = line == "g object_red_car";
    if (inside && line.rfind("v ", 0) == 0) {
      std::istringstream v(line.substr(2));
      Vec3 w;
      v >> w.x >> w.y >> w.z;
      vertices.push_back(w);
    }
  }
  ASSERT_EQ(vertices.size(), p.vertices.size());
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    const Vec3 expected = scene.objects[0].apply(p.vertices[i]) + scene.origin;
    ASSERT_NEAR(length(vertices[i] - expected), 0.0, 1e-3) << i;
  }
}

// The EXR's instance ids are instances.csv's rows: row i lists instance i, and every pixel
// whose first hit is a tree with id i lies on the tree standing where row i says.
TEST(SceneObj, InstanceIdsAreTheRowsOfInstancesCsv) {
  TempDir dir;
  const auto file = dir.write(
      "s.toml",
      "[terrain]\nelevation = \"" + source_file("data/terrain/volcano.asc").string() +
          "\"\n[sun]\nelevation = 40\nazimuth = 200\n[[species]]\nbit = 0\nfile = \"" +
          source_file("data/species/quaking_aspen.toml").string() +
          "\"\nvariants = 2\ndensity_per_ha = 30\ncover = { rectangle = [250.0, 700.0, 330.0, "
          "780.0] }\n[[views]]\nname = \"v\"\nposition = [290.0, 640.0, 140.0]\n"
          "target = [290.0, 740.0, 110.0]\nwidth = 64\nheight = 48\n");
  const renderer::Scene scene = scenes::build_scene(scenes::load_scenario(file));
  ASSERT_GT(scene.instances.size(), 5u);
  write_scene_obj(scene, dir / "scene.obj", {});
  std::ifstream csv(dir / "scene.instances.csv");
  std::vector<Vec3> rows;
  for (std::string line; std::getline(csv, line);) {
    if (line.empty() || line[0] == '#' || line.rfind("instance,", 0) == 0) continue;
    std::size_t id = 0, prototype = 0;
    Vec3 at;
    ASSERT_EQ(
        std::sscanf(line.c_str(), "%zu,%zu,%lf,%lf,%lf", &id, &prototype, &at.x, &at.y, &at.z), 5);
    EXPECT_EQ(id, rows.size());  // row index = instance id
    rows.push_back(at);
  }
  ASSERT_EQ(rows.size(), scene.instances.size());
  const renderer::Film film = renderer::Renderer(scene).render(scene.views[0], {});
  const renderer::Camera camera(scene.views[0]);
  int checked = 0;
  for (int y = 0; y < film.height(); ++y)
    for (int x = 0; x < film.width(); ++x) {
      const std::uint32_t id = film.instance(x, y);
      if (id == renderer::kNoId) continue;
      ASSERT_LT(id, rows.size());
      // Where the pixel's centre ray meets the tree (the first sample is jittered within the
      // pixel: a tree is metres wide, a pixel centimetres there).
      const renderer::Ray r = *camera.ray(float(x) + 0.5f, float(y) + 0.5f);
      const Vec3 hit = Vec3(r.origin) + double{film.depth(x, y)} * Vec3(r.direction);
      const Vec3 base = rows[id] - scene.origin;  // terrain frame -> scene frame
      EXPECT_LT(std::hypot(hit.x - base.x, hit.y - base.y), 12.0) << x << ", " << y;
      ++checked;
    }
  EXPECT_GT(checked, 50);
}

}  // namespace
}  // namespace landsim::exporters
