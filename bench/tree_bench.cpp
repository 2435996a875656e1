// Generation + meshing time of each species in the library (issue 3), one thread, seed 13.
// Species files are read once, outside the timed loop.
#include <benchmark/benchmark.h>

#include <filesystem>

#include "trees/species.h"

namespace {

using namespace landsim;

void BM_GenerateTree(benchmark::State& state, const std::string& file) {
  const trees::Species species =
      trees::load_species(std::filesystem::path(LANDSIM_SOURCE_DIR) / "data/species" / file);
  std::size_t triangles = 0;
  for (auto _ : state) {
    trees::Tree tree = trees::generate(species, {13});
    triangles = tree.geometry.triangle_count();
    benchmark::DoNotOptimize(tree);
  }
  state.counters["triangles"] = static_cast<double>(triangles);
}

const char* const kSpecies[] = {"barley.xml",
                                "black_tupelo.xml",
                                "ca_black_oak.xml",
                                "desert_bush.xml",
                                "eastern_cottonwood.xml",
                                "european_larch.xml",
                                "fanpalm.xml",
                                "lombardy_poplar.xml",
                                "palm.xml",
                                "quaking_aspen.xml",
                                "rush.xml",
                                "sassafras.xml",
                                "shave-grass.xml",
                                "tamarack.xml",
                                "weeping_willow.xml",
                                "wheat.xml"};

const bool kRegistered = [] {
  for (const char* file : kSpecies) {
    benchmark::RegisterBenchmark(("BM_GenerateTree/" + std::string(file)).c_str(), BM_GenerateTree,
                                 std::string(file))
        ->Unit(benchmark::kMillisecond);
  }
  return true;
}();

}  // namespace

BENCHMARK_MAIN();
