// [[ground.brdf]] (docs/GROUND.md "Reflectance models", docs/SCENARIO.md): the models read by
// material, the plain's, and what is refused (scenes/builder/detail/ground_models).
#include "scenes/builder/detail/ground_models.h"

#include <gtest/gtest.h>

#include "core/input_error.h"
#include "scenes/builder/scene_builder.h"
#include "tests/support/input_error_of.h"
#include "tests/support/temp_dir.h"

namespace landsim::scenes {
namespace {

using renderer::GroundBrdf;

std::string base(const std::string& albedo = "[0.2, 0.15, 0.1]") {
  return "[terrain]\nelevation = \"" +
         landsim::testing::source_file("data/terrain/volcano.asc").string() +
         "\"\nalbedo = " + albedo +
         "\n[sun]\nelevation = 40\nazimuth = 90\n"
         "[[views]]\nname = \"v\"\nposition = [300.0, -200.0, 400.0]\ntarget = [300.0, 400.0, "
         "150.0]\n";
}

renderer::Scene build(const std::string& text) {
  landsim::testing::TempDir dir;
  return build_scene(load_scenario(dir.write("s.toml", text)));
}

std::string refusal(const std::string& text) {
  return landsim::testing::input_error_of([&] { build(text); });
}

// Whether building `text` is refused with a message holding `what`.
::testing::AssertionResult refused_with(const std::string& text, const std::string& what) {
  const std::string message = refusal(text);
  if (message.find(what) != std::string::npos) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "refused with \"" << message << "\", not " << what;
}

TEST(GroundModels, OneTableShapesEveryMaterialButWaterAndLaterTablesOverride) {
  const renderer::Scene s = build(base() +
                                  "[[ground.brdf]]\nmodel = \"rpv\"\nk = 0.9\nasymmetry = -0.1\n"
                                  "[[ground.brdf]]\nmodel = \"ross-li\"\nvolumetric = 0.3\n"
                                  "geometric = 0.05\non = [\"rock\"]\n");
  for (std::size_t id : {0, 1, 4, 5, 8}) {
    EXPECT_EQ(s.ground.brdf[id].model, GroundBrdf::Model::rpv) << id;
    EXPECT_FLOAT_EQ(s.ground.brdf[id].k, 0.9f);
    EXPECT_FLOAT_EQ(s.ground.brdf[id].asymmetry, -0.1f);
    EXPECT_LT(s.ground.brdf[id].hot_spot, 0.0f);  // rho_c = rho_0
  }
  EXPECT_EQ(s.ground.brdf[2].model, GroundBrdf::Model::lambert);  // water
  EXPECT_EQ(s.ground.brdf[3].model, GroundBrdf::Model::ross_li);  // rock
  EXPECT_FLOAT_EQ(s.ground.brdf[3].volumetric, 0.3f);
  EXPECT_FLOAT_EQ(s.ground.brdf[3].geometric, 0.05f);
  EXPECT_EQ(s.ground.brdf_of(2), nullptr);
  EXPECT_NE(s.ground.brdf_of(0), nullptr);
  // By default the material's reflectance is the white-sky albedo: the model scaled to it.
  EXPECT_NEAR(renderer::white_sky_albedo(s.ground.brdf[0], 0.25), 0.25, 1e-4);
  EXPECT_NEAR(renderer::white_sky_albedo(s.ground.brdf[3], 0.25), 0.25, 1e-4);
}

TEST(GroundModels, AnIsotropicReflectanceIsTheModelsOwnParameter) {
  const renderer::Scene s = build(base() +
                                  "[[ground.brdf]]\nmodel = \"rpv\"\nk = 0.9\nasymmetry = -0.1\n"
                                  "reflectance = \"isotropic\"\n");
  EXPECT_EQ(s.ground.brdf[0].white_a, 1.0f);
  EXPECT_EQ(s.ground.brdf[0].white_ab, 0.0f);
  // RPV with rho_c = rho_0 reflects well above rho_0 overall: its hot-spot term is broad.
  EXPECT_GT(renderer::white_sky_albedo(s.ground.brdf[0], 0.2), 0.3);
}

TEST(GroundModels, ThePlainContinuesTheEdgesModelUnlessTheSurroundingsAreNamed) {
  // Grass everywhere, a model on the ground under grass alone: the edge is grass, and so is
  // the plain's reflection.
  const std::string grass = base() + "[[grass]]\ntype = 1\ncover = \"everywhere\"\n";
  const renderer::Scene s =
      build(grass + "[[ground.brdf]]\nmodel = \"rpv\"\nk = 0.8\non = [\"grass\"]\n");
  EXPECT_EQ(s.ground.brdf[0].model, GroundBrdf::Model::lambert);
  EXPECT_EQ(s.ground.brdf[renderer::Ground::kSurroundings].model, GroundBrdf::Model::rpv);
  EXPECT_FLOAT_EQ(s.ground.brdf[renderer::Ground::kSurroundings].k, 0.8f);
  const renderer::Scene named =
      build(grass +
            "[[ground.brdf]]\nmodel = \"rpv\"\nk = 0.8\non = [\"grass\"]\n"
            "[[ground.brdf]]\nmodel = \"lambert\"\non = [\"surroundings\"]\n");
  EXPECT_EQ(named.ground.brdf[renderer::Ground::kSurroundings].model, GroundBrdf::Model::lambert);
}

TEST(GroundModels, RefusesWaterOtherModelsKeysAndMoreLightThanArrives) {
  const std::string b = base();
  EXPECT_TRUE(refused_with(b + "[[ground.brdf]]\nmodel = \"rpv\"\non = [\"soil\", \"water\"]\n",
                           "[ground.brdf[0]] on: water reflects as a Fresnel mirror"));
  EXPECT_TRUE(refused_with(b + "[[ground.brdf]]\nmodel = \"ross-li\"\nk = 0.9\n",
                           "[ground.brdf[0]] k: an RPV parameter"));
  EXPECT_TRUE(refused_with(b + "[[ground.brdf]]\nmodel = \"rpv\"\nvolumetric = 0.1\n",
                           "[ground.brdf[0]] volumetric: a Ross-Li weight"));
  EXPECT_TRUE(
      refused_with(b + "[[ground.brdf]]\nmodel = \"lambert\"\nreflectance = \"isotropic\"\n",
                   "[ground.brdf[0]] reflectance"));
  EXPECT_TRUE(refused_with(b + "[[ground.brdf]]\nmodel = \"hapke\"\n", "[ground.brdf[0]] model"));
  EXPECT_TRUE(refused_with(b + "[[ground.brdf]]\nmodel = \"rpv\"\nasymmetry = 1.0\n",
                           "[ground.brdf[0]] asymmetry"));
  // A bright soil in a strong bowl: 0.9 x RPV(k = 0.3) reflects more than 1 at low suns.
  const std::string bright = refusal(base("[0.9, 0.9, 0.9]") +
                                     "[[ground.brdf]]\nmodel = \"rpv\"\nk = 0.3\n"
                                     "hot_spot = 0.0\non = [\"terrain\"]\n");
  EXPECT_NE(bright.find("s.toml:"), std::string::npos) << bright;
  EXPECT_NE(bright.find("[[ground.brdf]] on terrain"), std::string::npos) << bright;
  EXPECT_NE(bright.find("more than it receives"), std::string::npos) << bright;
  // The same model on rock, which this ground does not show, refuses nothing.
  EXPECT_EQ(refusal(base("[0.9, 0.9, 0.9]") +
                    "[[ground.brdf]]\nmodel = \"rpv\"\nk = 0.3\nhot_spot = 0.0\n"
                    "on = [\"rock\"]\n"),
            "");
  // A milder bowl on a dark soil is fine.
  EXPECT_EQ(refusal(base("[0.1, 0.1, 0.1]") +
                    "[[ground.brdf]]\nmodel = \"rpv\"\nk = 0.7\nhot_spot = 0.0\n"
                    "on = [\"terrain\"]\n"),
            "");
}

}  // namespace
}  // namespace landsim::scenes
