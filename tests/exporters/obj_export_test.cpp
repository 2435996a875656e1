// The scene OBJ carries the scene objects in place, in terrain coordinates.
#include "exporters/obj_export.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "scenes/scene_builder.h"
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

}  // namespace
}  // namespace landsim::exporters
