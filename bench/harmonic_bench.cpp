// Harmonic core (issue 11): particles per second and total time for a tree of about 15,000
// particles (the paper: 2.4 s), one thread; growth alone and growth with meshing; and the six
// example species. The 15,000-particle tree is the paper birch with five levels and
// level-1 buds living 60 steps.
#include <benchmark/benchmark.h>

#include <filesystem>

#include "trees/harmonic/generator.h"
#include "trees/mesher.h"
#include "trees/species.h"

namespace {

using namespace landsim::trees;

harmonic::Parameters species(const std::string& file) {
  return std::get<harmonic::Parameters>(
      load_species(std::filesystem::path(LANDSIM_SOURCE_DIR) / "data/species" / file).parameters);
}

harmonic::Parameters fifteen_thousand() {
  harmonic::Parameters p = species("harmonic_paper_birch.toml");
  p.values[2] = 5;    // levels
  p.values[22] = 60;  // hierarchy[1].terminal_age
  return p;
}

void BM_HarmonicGrowth(benchmark::State& state) {
  const harmonic::Parameters p = fifteen_thousand();
  std::size_t particles = 0;
  for (auto _ : state) particles = harmonic::grow(p, 1).particles();
  state.counters["particles"] = static_cast<double>(particles);
  state.counters["particles_per_s"] = benchmark::Counter(
      static_cast<double>(particles), benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_HarmonicGrowth)->Unit(benchmark::kMillisecond);

void BM_HarmonicTree(benchmark::State& state) {  // growth, skeleton and mesh
  const harmonic::Parameters p = fifteen_thousand();
  std::size_t triangles = 0;
  for (auto _ : state)
    triangles = mesh_tree(harmonic::generate_skeleton(p, 1), MeshResolution{}).triangle_count();
  state.counters["triangles"] = static_cast<double>(triangles);
}
BENCHMARK(BM_HarmonicTree)->Unit(benchmark::kMillisecond);

void BM_HarmonicSpecies(benchmark::State& state, const std::string& file) {
  const harmonic::Parameters p = species(file);
  harmonic::Growth g;
  for (auto _ : state) benchmark::DoNotOptimize(harmonic::generate_skeleton(p, 1, {}, &g));
  state.counters["particles"] = static_cast<double>(g.particles());
}

// The paper's own figure (Hoetzlein 2022 section 4: a paper birch of 15,146 particles in
// 2.4 s, 687 unique branches) against the birch of the species file as it is, not tuned:
// its particles, chains (branches), leaves and triangles; growth, skeleton and mesh timed.
void BM_PaperBirchSpeciesFile(benchmark::State& state) {
  const harmonic::Parameters p = species("harmonic_paper_birch.toml");
  harmonic::Growth g;
  std::size_t triangles = 0, leaves = 0;
  for (auto _ : state) {
    const TreeSkeleton skeleton = harmonic::generate_skeleton(p, 1, {}, &g);
    leaves = skeleton.leaves.size();
    triangles = mesh_tree(skeleton, MeshResolution{}).triangle_count();
  }
  state.counters["particles"] = static_cast<double>(g.particles());
  state.counters["chains"] = static_cast<double>(g.chains.size());
  state.counters["leaves"] = static_cast<double>(leaves);
  state.counters["triangles"] = static_cast<double>(triangles);
}
BENCHMARK(BM_PaperBirchSpeciesFile)->Unit(benchmark::kMillisecond);

const bool kRegistered = [] {
  for (const char* file :
       {"harmonic_ponderosa_pine.toml", "harmonic_snow_gum.toml", "harmonic_paper_birch.toml",
        "harmonic_cherry.toml", "harmonic_american_elm.toml", "harmonic_juniper.toml"})
    benchmark::RegisterBenchmark(("BM_HarmonicSpecies/" + std::string(file)).c_str(),
                                 BM_HarmonicSpecies, std::string(file))
        ->Unit(benchmark::kMillisecond);
  return true;
}();

}  // namespace

BENCHMARK_MAIN();
