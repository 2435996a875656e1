#include "exporters/pov_export.h"

#include <gtest/gtest.h>

#include "tests/renderer/measures/canopy_cells.h"
#include "tests/support/temp_dir.h"

namespace landsim::exporters {
namespace {

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

// An abstract canopy's leaves are discs in POV-Ray too: every one, drawn with the leaves'
// reflectance in each tree that uses the cloud.
TEST(PovExport, LeafCloudsAreWrittenAsTheirDiscs) {
  renderer::Scene s = renderer::testing::canopy_cell(30.0, 0.0);
  renderer::View view;
  view.position = {-30.0, -30.0, 20.0};
  view.target = {0.0, 0.0, 3.0};
  s.views.push_back(view);
  const landsim::testing::TempDir dir;
  export_pov(s, view, dir.path(), {});
  const std::string meshes = landsim::testing::read_file(dir.path() / "meshes.inc");
  const std::string scene = landsim::testing::read_file(dir.path() / "scene.pov");
  EXPECT_EQ(count(meshes, "  disc {"),
            s.prototypes[0].geometry.group(trees::Group::leaves).points.point_count());
  EXPECT_EQ(count(scene, "object { LS_Proto_0_discs LS_Texture(<0, 0, 1>, <0.45, 0.45, 0.45>)"),
            1u);
  EXPECT_EQ(count(scene, "object { LS_Tree_0 "), 1u);
}

}  // namespace
}  // namespace landsim::exporters
