#include "scenes/builder/memory_estimate.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <regex>

#include "core/input_error.h"
#include "core/process_memory.h"
#include "scenes/builder/scene_builder.h"
#include "scenes/scenario/default_scenario.h"
#include "tests/support/temp_dir.h"

namespace landsim::scenes {
namespace {

// The part whose name starts with `prefix` ("tree instances (2194 trees)").
std::size_t part(const MemoryEstimate& e, const std::string& prefix) {
  for (const MemoryPart& p : e.parts)
    if (p.name.rfind(prefix, 0) == 0) return p.bytes;
  return 0;
}

TEST(MemoryEstimate, CountsWhatTheBuilderPlacesWithoutPlacingIt) {
  const Scenario s = default_scenario();
  const MemoryEstimate e = estimate_memory(s);
  const renderer::Scene scene = build_scene(s);
  const auto placed = static_cast<double>(scene.instances.size());
  EXPECT_NEAR(e.instances, placed, 0.1 * placed);
  std::vector<double> per_species(s.species.size(), 0.0);
  for (const renderer::TreeInstance& t : scene.instances)
    per_species[scene.prototypes[t.prototype].species] += 1.0;
  for (std::size_t k = 0; k < s.species.size(); ++k)
    EXPECT_NEAR(e.instances_per_species.at(s.species[k].species.name), per_species[k],
                0.1 * per_species[k])
        << s.species[k].species.name;
  EXPECT_EQ(e.unique_variants, scene.prototypes.size());
  std::size_t tiles = 0;
  for (std::uint8_t t : scene.grass.type) tiles += t != 0 ? 1 : 0;
  EXPECT_EQ(e.grass_tiles, tiles);
  double triangles = static_cast<double>(scene.ground.mesh.triangle_count());
  for (const renderer::TreePrototype& p : scene.prototypes)
    triangles += static_cast<double>(p.geometry.triangle_count());
  EXPECT_NEAR(e.triangles_stored, triangles, 0.25 * triangles);
}

// The estimate reads the build's own first stages (scenes/builder/detail/scene_foundation), so
// grass kept off a road raster is kept off in the estimate too (it replayed the build without the
// road and water masks before, and counted grass on the road).
TEST(MemoryEstimate, GrassOffTheRoadIsOffInTheEstimateAndTheRoadIsCounted) {
  landsim::testing::TempDir dir;
  std::string road =
      "ncols 61\nnrows 87\nxllcorner 0.0\nyllcorner 0.0\ncellsize 10.0\n"
      "NODATA_value -9999\n";
  for (int r = 0; r < 87; ++r) {
    for (int c = 0; c < 61; ++c) road += c < 30 ? "1 " : "0 ";
    road += "\n";
  }
  dir.write("road.asc", road);
  const std::string base =
      "[terrain]\nelevation = \"" +
      landsim::testing::source_file("data/terrain/volcano.asc").string() +
      "\"\n[sun]\nelevation = 30\nazimuth = 200\n[[views]]\nname = \"v\"\n"
      "position = [300.0, -200.0, 300.0]\ntarget = [300.0, 400.0, 120.0]\nwidth = 64\n"
      "height = 36\n[[grass]]\ntype = 1\ncover = \"everywhere\"\n";
  const Scenario open = parse_scenario(base, "open.toml", dir.path().string());
  const Scenario with_road = parse_scenario(base + "[featuremaps]\nroad = \"road.asc\"\n",
                                            "road.toml", dir.path().string());
  const MemoryEstimate e = estimate_memory(with_road);
  const renderer::Scene scene = build_scene(with_road);
  std::size_t tiles = 0;
  for (std::uint8_t t : scene.grass.type) tiles += t != 0 ? 1 : 0;
  EXPECT_EQ(e.grass_tiles, tiles);
  EXPECT_LT(e.grass_tiles, estimate_memory(open).grass_tiles * 3 / 4);  // half is road
}

TEST(MemoryEstimate, PartsScaleWithWhatTheyCount) {
  const Scenario s = default_scenario();
  const MemoryEstimate base = estimate_memory(s);
  Scenario dense = s;
  for (SpeciesSettings& sp : dense.species) {
    sp.density_per_ha *= 10.0;
    sp.min_spacing = 0.0;
  }
  const MemoryEstimate e = estimate_memory(dense);
  EXPECT_NEAR(e.instances / base.instances, 10.0, 0.5);
  const double ratio = static_cast<double>(part(e, "tree instances")) /
                       static_cast<double>(part(base, "tree instances"));
  EXPECT_NEAR(ratio, 10.0, 0.5);
  Scenario large = s;
  large.views[0].width *= 4;
  large.views[0].height *= 4;
  const double film = static_cast<double>(part(estimate_memory(large), "image")) /
                      static_cast<double>(part(base, "image"));
  EXPECT_NEAR(film, 16.0, 0.1);
}

// Leaf clouds are counted: HET01's 49,999 discs (the file's, the prototype's, Embree's) and
// its 15 copies; a generated cloud's part grows with its discs times its variants.
TEST(MemoryEstimate, LeafCloudsAreCounted) {
  Scenario s = load_scenario(landsim::testing::source_file("scenes/rami/het01.toml"));
  const double het01 = static_cast<double>(part(estimate_memory(s), "leaf clouds"));
  EXPECT_GT(het01, 49999.0 * 100.0);
  EXPECT_LT(het01, 49999.0 * 200.0);
  CanopySettings& c = s.canopies.front();
  c.discs.clear();
  c.generated = GeneratedCloud{};
  c.generated->discs = 10000;
  const double small = static_cast<double>(part(estimate_memory(s), "leaf clouds"));
  c.generated->variants = 4;
  c.generated->discs = 20000;
  const double large = static_cast<double>(part(estimate_memory(s), "leaf clouds"));
  EXPECT_NEAR((large - small) / small, 7.0, 0.1);  // 8x the discs, the same 15 copies
}

// The default view sees its trees from afar: degraded, their variants hold a fraction of
// their full-detail primitives in Embree.
TEST(MemoryEstimate, DegradationOffHoldsEveryVariantAtFullDetail) {
  Scenario s = default_scenario();
  const std::size_t on = part(estimate_memory(s), "tree variants");
  s.render.degradation = false;
  const std::size_t off = part(estimate_memory(s), "tree variants");
  EXPECT_GT(off, on + on / 2);
}

TEST(MemoryEstimate, PartsAreListedLargestFirstAndSumToTheTotal) {
  const MemoryEstimate e = estimate_memory(default_scenario());
  ASSERT_GE(e.parts.size(), 4u);
  EXPECT_TRUE(
      std::is_sorted(e.parts.begin(), e.parts.end(),
                     [](const MemoryPart& a, const MemoryPart& b) { return a.bytes > b.bytes; }));
  std::size_t sum = e.program_bytes;
  for (const MemoryPart& p : e.parts) sum += p.bytes;
  EXPECT_EQ(e.total_bytes(), sum);
  EXPECT_GT(e.program_bytes, 0u);
}

// The scene builder takes the estimate's variants instead of generating them again, and
// builds the same scene.
TEST(MemoryEstimate, ItsVariantsAreTheOnesTheBuilderWouldGenerate) {
  const Scenario s = default_scenario();
  VariantCache variants;
  estimate_memory(s, &variants);
  ASSERT_EQ(variants.trees.size(), s.species.size());
  const renderer::Scene reused = build_scene(s, 0.0, &variants);
  const renderer::Scene fresh = build_scene(s, 0.0);
  ASSERT_EQ(reused.prototypes.size(), fresh.prototypes.size());
  for (std::size_t i = 0; i < fresh.prototypes.size(); ++i) {
    const trees::TreeGeometry& a = reused.prototypes[i].geometry;
    const trees::TreeGeometry& b = fresh.prototypes[i].geometry;
    for (int g = 0; g < trees::kGroupCount; ++g) {
      const auto k = static_cast<std::size_t>(g);
      EXPECT_EQ(a.groups[k].triangles.vertices, b.groups[k].triangles.vertices);
      EXPECT_EQ(a.groups[k].triangles.indices, b.groups[k].triangles.indices);
    }
    EXPECT_EQ(reused.prototypes[i].leaf_reflectance, fresh.prototypes[i].leaf_reflectance);
  }
  // Taken (moved out), not generated again.
  for (const auto& [key, variant] : variants.trees)
    EXPECT_EQ(variant.geometry.triangle_count(), 0u) << "species " << key.species;
}

// docs/PERFORMANCE.md records the estimate against the measured peak (bench/memory.sh): the
// three calibration scenes must be there, each within 25%, ratios consistent with the sizes.
TEST(MemoryEstimate, RecordedPeaksAreWithinAQuarterOfTheEstimate) {
  const std::string doc =
      landsim::testing::read_file(landsim::testing::source_file("docs/PERFORMANCE.md"));
  const std::size_t section = doc.find("## Memory budget");
  ASSERT_NE(section, std::string::npos);
  const std::regex row(R"(\| ([^|]+) \| [0-9,]+ \| (\d+) MB \| (\d+) MB \| ([0-9.]+) \|)");
  std::vector<std::string> scenes;
  const std::string text = doc.substr(section);
  for (auto it = std::sregex_iterator(text.begin(), text.end(), row); it != std::sregex_iterator();
       ++it) {
    const std::smatch& m = *it;
    const double estimate = std::stod(m[2]), peak = std::stod(m[3]), ratio = std::stod(m[4]);
    EXPECT_NEAR(ratio, estimate / peak, 0.006) << m[1];
    EXPECT_GE(ratio, 0.75) << m[1];
    EXPECT_LE(ratio, 1.25) << m[1];
    scenes.push_back(m[1]);
  }
  for (const char* name : {"default", "Kagwene", "100 k trees"})
    EXPECT_NE(std::find_if(scenes.begin(), scenes.end(),
                           [&](const std::string& s) { return s.rfind(name, 0) == 0; }),
              scenes.end())
        << name << " is not in the table";
}

TEST(MemoryBudget, RefusesAnEstimateOverItNamingTheLargestParts) {
  const MemoryEstimate e = estimate_memory(default_scenario());
  EXPECT_NO_THROW(check_memory_budget(e, e.total_bytes(), "--max-memory"));
  try {
    check_memory_budget(e, e.total_bytes() - 1, "--max-memory");
    FAIL() << "an estimate over the budget passed";
  } catch (const InputError& error) {
    const std::string m = error.what();
    EXPECT_NE(m.find(e.scenario), std::string::npos) << m;
    EXPECT_NE(m.find("--max-memory"), std::string::npos) << m;
    EXPECT_NE(m.find(e.parts.front().name), std::string::npos) << m;
    EXPECT_NE(m.find(e.parts.front().remedy), std::string::npos) << m;
  }
}

TEST(MemoryBudget, DefaultIsAShareOfPhysicalMemoryPerRank) {
  const MemoryBudget one = default_memory_budget(1);
  EXPECT_GT(one.bytes, 0u);
  EXPECT_LE(one.bytes, physical_memory_bytes());
  const MemoryBudget four = default_memory_budget(4);
  EXPECT_NEAR(static_cast<double>(four.bytes), static_cast<double>(one.bytes) / 4.0, 1.0);
  EXPECT_NE(four.source.find("4 ranks"), std::string::npos) << four.source;
}

TEST(MemoryBudget, ScenarioSizesTakeUnits) {
  const std::string dem = landsim::testing::source_file("data/terrain/volcano.asc").string();
  const auto max_memory = [&](const std::string& value) {
    return parse_scenario("[terrain]\nelevation = \"" + dem +
                              "\"\n[sun]\nelevation = 30\nazimuth = 90\n[[views]]\nname = \"v\"\n"
                              "position = [0.0, 0.0, 10.0]\ntarget = [1.0, 1.0, 0.0]\n"
                              "[render]\nmax_memory = " +
                              value + "\n",
                          "s.toml", ".")
        .render.max_memory;
  };
  EXPECT_EQ(max_memory("\"8 GB\""), 8'000'000'000u);
  EXPECT_EQ(max_memory("\"512MiB\""), 512u * 1024u * 1024u);
  EXPECT_EQ(max_memory("1000000"), 1'000'000u);
  for (const std::string bad : {"\"lots\"", "0", "-5", "1.5"}) {
    try {
      max_memory(bad);
      FAIL() << bad << " was accepted";
    } catch (const InputError& error) {
      EXPECT_TRUE(std::regex_search(error.what(), std::regex("s\\.toml:\\d+:\\d+.*max_memory")))
          << error.what();
    }
  }
}

}  // namespace
}  // namespace landsim::scenes
