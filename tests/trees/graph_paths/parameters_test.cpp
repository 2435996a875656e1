#include "trees/graph_paths/parameters.h"

#include <gtest/gtest.h>

#include "tests/trees/species_files.h"

#include <cmath>
#include <numbers>

#include "core/input_error.h"
#include "tests/support/temp_dir.h"
#include "trees/species.h"

namespace landsim::trees::graph_paths {
namespace {

const std::string kHeader = "core = \"graph_paths\"\n";
const std::string kVolume = "[[volume]]\nkind = \"sphere\"\nradius = 1.0\n";

std::string error_of(const std::string& text) {
  return trees::testing::species_error(text, "g.toml");
}

TEST(GraphPathsSpecies, ReadsEveryTable) {
  const Species s = parse_species_toml(
      kHeader +
          "name = \"t\"\n[graph]\nspacing = 0.2\npolicy = \"threshold\"\nthreshold = 1.8\n"
          "endpoints = 50\nshell = 0.25\nroot = [0, 0, -1]\n[thickness]\npower = 2.0\n"
          "[leaves]\nper_endpoint = 4\n[[volume]]\nkind = \"sphere_portion\"\nradius = 2.0\n"
          "half_angle = 60\naxis = [0, 0, 2]\n",
      "t.toml");
  EXPECT_EQ(core_name(s), "graph_paths");
  const auto& p = std::get<Parameters>(s.parameters);
  EXPECT_DOUBLE_EQ(p.spacing, 0.2);
  EXPECT_EQ(p.policy, GraphPolicy::threshold);
  EXPECT_DOUBLE_EQ(p.threshold, 1.8);
  EXPECT_EQ(p.endpoints, 50);
  EXPECT_DOUBLE_EQ(p.root.z, -1.0);
  EXPECT_DOUBLE_EQ(p.skeleton.thickness_power, 2.0);
  EXPECT_EQ(p.skeleton.leaves_per_endpoint, 4);
  ASSERT_EQ(p.volume.parts().size(), 1u);
  EXPECT_EQ(p.volume.parts()[0].kind, PrimitiveKind::sphere_portion);
  EXPECT_NEAR(p.volume.parts()[0].half_angle, std::numbers::pi / 3, 1e-12);
  EXPECT_DOUBLE_EQ(p.volume.parts()[0].axis.z, 1.0);  // normalised
}

TEST(GraphPathsSpecies, ReadsTheRefinement) {
  const Species s = parse_species_toml(
      kHeader +
          "[refinement]\nspheres = 4\nradius = 1.5\ncone_ratio = 0.3\njunction = [0, 0, 2]\n" +
          kVolume,
      "r.toml");
  const auto& p = std::get<Parameters>(s.parameters);
  EXPECT_EQ(p.refinement.spheres, 4);
  EXPECT_DOUBLE_EQ(p.refinement.radius, 1.5);
  EXPECT_DOUBLE_EQ(p.refinement.cone_ratio, 0.3);
  EXPECT_DOUBLE_EQ(p.junction.z, 2.0);
  const std::string msg = error_of(kHeader + "[refinement]\nspheres = 99\n" + kVolume);
  EXPECT_NE(msg.find("[refinement] spheres"), std::string::npos) << msg;
}

TEST(GraphPathsSpecies, BadShapesAndParametersNameTheLineAndKey) {
  std::string msg = error_of(kHeader + "[[volume]]\nkind = \"torus\"\n");
  EXPECT_NE(msg.find("g.toml:3:"), std::string::npos) << msg;
  EXPECT_NE(msg.find("[volume[0]] kind"), std::string::npos) << msg;
  msg = error_of(kHeader + kVolume + "radius2 = 3\n");
  EXPECT_NE(msg.find("unknown key 'radius2'"), std::string::npos) << msg;
  msg = error_of(kHeader + "[graph]\ncone_subdivisions = 2\n" + kVolume);
  EXPECT_NE(msg.find("g.toml:3:"), std::string::npos) << msg;
  EXPECT_NE(msg.find("from 3 to 8"), std::string::npos) << msg;
  msg = error_of(kHeader + "[[volume]]\nkind = \"cone\"\naxis = [0, 0, 0]\n");
  EXPECT_NE(msg.find("[volume[0]] axis"), std::string::npos) << msg;
  msg = error_of(kHeader + "[[volume]]\nradius = 1.0\n");
  EXPECT_NE(msg.find("[volume[0]] kind"), std::string::npos) << msg;
  msg = error_of(kHeader +
                 "[[volume]]\nkind = \"revolution\"\nprofile = [[0, 1], [2, 1], [1, 0.5]]\n");
  EXPECT_NE(msg.find("g.toml:4:"), std::string::npos) << msg;
  EXPECT_NE(msg.find("heights strictly increasing"), std::string::npos) << msg;
  msg = error_of(kHeader + "[[volume]]\nkind = \"revolution\"\n");
  EXPECT_NE(msg.find("[volume[0]] profile"), std::string::npos) << msg;
  msg = error_of(kHeader + "[graph]\nspacing = 0.1\n");
  EXPECT_NE(msg.find("[[volume]] is required"), std::string::npos) << msg;
  msg = error_of(kHeader + "Scale = 3\n" + kVolume);
  EXPECT_NE(msg.find("Scale"), std::string::npos) << msg;
}

TEST(GraphPathsSpecies, ManualEndpointsAreReadAndCheckedAgainstTheVolume) {
  const Species s = parse_species_toml(
      kHeader + "[graph]\nmanual_endpoints = [[0.5, 0, 0.2], [0, -0.5, 0.5]]\n" + kVolume,
      "g.toml");
  const auto& p = std::get<Parameters>(s.parameters);
  ASSERT_EQ(p.manual_endpoints.size(), 2u);
  EXPECT_EQ(p.manual_endpoints[1], (Vec3{0, -0.5, 0.5}));
  const std::string outside =
      error_of(kHeader + "[graph]\nmanual_endpoints = [[0, 0, 0.5], [3, 0, 0]]\n" + kVolume);
  EXPECT_NE(outside.find("manual_endpoints[1] (3, 0, 0) is outside"), std::string::npos) << outside;
  const std::string malformed =
      error_of(kHeader + "[graph]\nmanual_endpoints = [[0, 0]]\n" + kVolume);
  EXPECT_NE(malformed.find("g.toml:3"), std::string::npos) << malformed;
  EXPECT_NE(malformed.find("[[x, y, z], ...]"), std::string::npos) << malformed;
}

TEST(GraphPathsSpecies, ExplosiveSpacingIsRefusedBeforeGenerating) {
  // A 10 m sphere at 5 cm spacing: about 19 million nodes.
  const std::string msg =
      error_of(kHeader + "[graph]\nspacing = 0.05\n[[volume]]\nkind = \"sphere\"\nradius = 10\n");
  EXPECT_NE(msg.find("g.toml:"), std::string::npos) << msg;
  EXPECT_NE(msg.find("[graph] spacing 0.05"), std::string::npos) << msg;
  EXPECT_NE(msg.find("limit"), std::string::npos) << msg;
  // Iterated levels multiply: 200 endpoints x 64^5 subgraphs.
  const std::string deep =
      error_of(kHeader + "[iteration]\nlevels = 6\nendpoints = 64\n" + kVolume);
  EXPECT_NE(deep.find("6 [iteration] levels"), std::string::npos) << deep;
  EXPECT_EQ(error_of(kHeader + "[iteration]\nlevels = 2\nendpoints = 4\n" + kVolume), "");
  // Roots too fine: the [roots] keys are named, at the file's line (before, the message
  // blamed graph.spacing and the iteration levels).
  const std::string roots =
      error_of(kHeader + "[roots]\nradius = 20\ndepth = 20\nspacing = 0.01\n" + kVolume);
  EXPECT_NE(roots.find("g.toml:"), std::string::npos) << roots;
  EXPECT_NE(roots.find("[roots] spacing 0.01 with radius 20"), std::string::npos) << roots;
  EXPECT_EQ(roots.find("[graph] spacing"), std::string::npos) << roots;
}

TEST(GraphPathsSpecies, EstimatedNodesMatchesASampledVolume) {
  Parameters p;
  VolumePrimitive sphere;
  p.volume = InitialVolume({sphere});
  p.spacing = 0.1;
  const double estimate = estimated_nodes(p);
  GraphStatistics stats;
  generate_skeleton(p, 1, &stats);
  EXPECT_NEAR(static_cast<double>(stats.nodes), estimate, 0.1 * estimate);
}

TEST(GraphPathsSpecies, TheSixExampleSpeciesGenerateDistinctShapes) {
  // Sizes follow from each file's volumes and subgraph reach: e.g. the bush is a 1 m dome,
  // the round crown's limb spheres (1.4 m) reach at most 5 m out with their subgraphs, the conifer
  // a 9 m cone of 1.8 m base radius, the umbrella a flat crown 4 m wide at 5 m.
  testing::expect_shapes("graph_paths",
                         {{"graph_round_crown.toml", 6, 10, 2.4, 5.2},
                          {"graph_conifer.toml", 8, 10.5, 1.5, 3.0},
                          {"graph_willow.toml", 6.5, 9, 3.0, 5.5},
                          {"graph_bush.toml", 1.0, 2.2, 1.0, 2.2},
                          {"graph_column.toml", 9.5, 12, 0.8, 2.0},
                          {"graph_umbrella.toml", 5.5, 8, 3.8, 5.5}},
                         3, 1000);
}

}  // namespace
}  // namespace landsim::trees::graph_paths
