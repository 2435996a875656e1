// The legend names every id the species layer holds: the [[species]] in order, then the
// [[canopy]] clouds, whose leaves carry the ids the builder gives them.
#include "scenes/image_set/detail/legend.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "scenes/builder/scene_builder.h"
#include "scenes/scenario/scenario.h"
#include "tests/support/temp_dir.h"

namespace landsim::scenes {
namespace {

TEST(Legend, NamesTheCanopiesAfterTheSpecies) {
  const Scenario s = load_scenario(landsim::testing::source_file("scenes/rami/het01.toml"));
  const nlohmann::json values = detail::legend(s)["species"]["values"];
  ASSERT_EQ(values.size(), s.species.size() + s.canopies.size());
  const renderer::Scene scene = build_scene(s);
  for (std::size_t k = 0; k < s.canopies.size(); ++k) {
    const nlohmann::json& v = values[s.species.size() + k];
    EXPECT_EQ(v["name"], s.canopies[k].name);
    EXPECT_EQ(v["core"], "canopy");
    // Some prototype of the scene is this cloud's, with the legend's id.
    bool found = false;
    for (const renderer::TreePrototype& p : scene.prototypes)
      found |= p.leaf_discs && p.species == v["id"].get<std::uint16_t>();
    EXPECT_TRUE(found) << v.dump();
  }
}

}  // namespace
}  // namespace landsim::scenes
