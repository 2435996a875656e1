// Placement of 1,000,000 trees (issue 5): a 10 km x 10 km vegetation map of 10 m cells all
// selecting one species at 100 trees per hectare, on flat terrain. Reports the time per
// placement and the peak resident memory of the process.
#include <benchmark/benchmark.h>
#include <sys/resource.h>

#include "featuremaps/placement.h"

namespace {

using namespace landsim;

void BM_PlaceMillionTrees(benchmark::State& state) {
  const int cells = 1000;
  const featuremaps::VegetationMap map(
      cells, cells, terrain::GeoTransform{0.0, 10000.0, 10.0, 10.0},
      std::vector<std::uint16_t>(static_cast<std::size_t>(cells) * cells, 1));
  const terrain::ElevationGrid ground(101, 101, terrain::GeoTransform{-50.0, 10050.0, 100.0, 100.0},
                                      std::vector<float>(101 * 101, 100.0f));
  const std::vector<featuremaps::SpeciesPlacement> species{{0, 100.0, 2.0, 8, 0.2}};
  std::size_t placed = 0;
  for (auto _ : state) {
    const auto trees = featuremaps::place_trees(map, ground, species, 1);
    placed = trees.size();
    benchmark::DoNotOptimize(trees.data());
  }
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  state.counters["trees"] = static_cast<double>(placed);
  state.counters["peak_rss_MB"] = static_cast<double>(usage.ru_maxrss) / 1024.0;
}
BENCHMARK(BM_PlaceMillionTrees)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
