// Self-organising core (issue 9): growth time for trees of about 10,000 and 100,000
// internodes, one thread, and per step; and the seven example species. The so_upright
// species grows autonomously (markers in every bud's cone each step); the step count sets
// the size. Reported: internodes, steps (time per step = time / steps), peak RSS.
#include <benchmark/benchmark.h>
#include <sys/resource.h>

#include <filesystem>

#include "trees/self_organizing/generator.h"
#include "trees/species.h"

namespace {

using namespace landsim::trees::self_organizing;

double peak_rss_mb() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;
}

Parameters species(const std::string& file) {
  return std::get<Parameters>(landsim::trees::load_species(
                                  std::filesystem::path(LANDSIM_SOURCE_DIR) / "data/species" / file)
                                  .parameters);
}

void BM_SelfOrganizingGrowth(benchmark::State& state) {
  Parameters p = species("so_upright.toml");
  p.steps = static_cast<int>(state.range(0));
  GrowthStatistics stats;
  for (auto _ : state) benchmark::DoNotOptimize(grow(p, 1, &stats));
  state.counters["internodes"] = static_cast<double>(stats.internodes);
  state.counters["steps"] = stats.steps;
  state.counters["peak_rss_MB"] = peak_rss_mb();
}
// 16 steps: about 10,000 internodes; 32 steps: 93,000, near the limit of 100,000 (33 steps
// would pass it).
BENCHMARK(BM_SelfOrganizingGrowth)->Arg(16)->Arg(32)->Unit(benchmark::kMillisecond);

void BM_SelfOrganizingSpecies(benchmark::State& state, const std::string& file) {
  const Parameters p = species(file);
  GrowthStatistics stats;
  for (auto _ : state) benchmark::DoNotOptimize(generate_skeleton(p, 13, &stats));
  state.counters["internodes"] = static_cast<double>(stats.internodes);
  state.counters["steps"] = stats.steps;
}

const bool kRegistered = [] {
  for (const char* file :
       {"so_upright.toml", "so_plagiotropic.toml", "so_weeping.toml", "so_epitonic.toml",
        "so_shedding.toml", "so_envelope.toml", "so_brushed.toml"})
    benchmark::RegisterBenchmark(("BM_SelfOrganizingSpecies/" + std::string(file)).c_str(),
                                 BM_SelfOrganizingSpecies, std::string(file))
        ->Unit(benchmark::kMillisecond);
  return true;
}();

}  // namespace

BENCHMARK_MAIN();
