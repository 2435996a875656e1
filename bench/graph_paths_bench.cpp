// Xu & Mould graph stages against graph size (issue 8): Poisson-disc nodes in a unit sphere,
// the Yao graph, Dijkstra from the root and the union of 1,000 endpoint paths, one thread.
// The spacing sets the node count; "nodes" and the process's peak RSS are reported.
#include <benchmark/benchmark.h>
#include <sys/resource.h>

#include <cmath>
#include <filesystem>

#include "trees/graph_paths/endpoints.h"
#include "trees/graph_paths/generator.h"
#include "trees/graph_paths/least_cost_paths.h"
#include "trees/graph_paths/poisson_disc.h"
#include "trees/species.h"

namespace {

using namespace landsim::trees::graph_paths;

double peak_rss_mb() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;
}

void BM_GraphPaths(benchmark::State& state) {
  const double spacing = static_cast<double>(state.range(0)) / 1000.0;
  VolumePrimitive sphere;
  const InitialVolume volume({sphere});
  std::size_t nodes = 0, structure = 0;
  for (auto _ : state) {
    std::vector<landsim::Vec3> points = poisson_disc(volume, {.spacing = spacing}, 1);
    nodes = points.size();
    const Graph g = build_graph(std::move(points), {.search_radius = 2.5 * spacing}, 1);
    const auto endpoints = shell_endpoints(g.nodes, volume, 2.0 * spacing, 1000, 1);
    const PathTree tree = least_cost_tree(g, nearest_node(g.nodes, {0, 0, -1}));
    const BranchStructure b = union_of_paths(g, tree, endpoints);
    structure = b.node.size();
    benchmark::DoNotOptimize(b);
  }
  state.counters["nodes"] = static_cast<double>(nodes);
  state.counters["structure"] = static_cast<double>(structure);
  state.counters["peak_rss_MB"] = peak_rss_mb();
}
// Spacing in millimetres in a 1 m sphere: about 5.6 k, 44 k, 142 k and 355 k nodes.
BENCHMARK(BM_GraphPaths)->Arg(80)->Arg(40)->Arg(27)->Arg(20)->Unit(benchmark::kMillisecond);

// The stages alone, to see where the time of BM_GraphPaths goes.
void BM_PoissonDisc(benchmark::State& state) {
  const double spacing = static_cast<double>(state.range(0)) / 1000.0;
  const InitialVolume volume({VolumePrimitive{}});
  std::size_t nodes = 0;
  for (auto _ : state) nodes = poisson_disc(volume, {.spacing = spacing}, 1).size();
  state.counters["nodes"] = static_cast<double>(nodes);
}
BENCHMARK(BM_PoissonDisc)->Arg(27)->Unit(benchmark::kMillisecond);

void BM_YaoGraph(benchmark::State& state) {
  const double spacing = static_cast<double>(state.range(0)) / 1000.0;
  const InitialVolume volume({VolumePrimitive{}});
  const std::vector<landsim::Vec3> points = poisson_disc(volume, {.spacing = spacing}, 1);
  std::size_t edges = 0;
  for (auto _ : state)
    edges = build_graph(points, {.search_radius = 2.5 * spacing}, 1).neighbours.size();
  state.counters["nodes"] = static_cast<double>(points.size());
  state.counters["edges"] = static_cast<double>(edges);
}
BENCHMARK(BM_YaoGraph)->Arg(27)->Unit(benchmark::kMillisecond);

// The six example species, whole trees (all levels, meshing excluded): nodes in all graphs.
void BM_GraphSpecies(benchmark::State& state, const std::string& file) {
  const landsim::trees::Species species = landsim::trees::load_species(
      std::filesystem::path(LANDSIM_SOURCE_DIR) / "data/species" / file);
  const auto& p = std::get<Parameters>(species.parameters);
  GraphStatistics stats;
  for (auto _ : state) benchmark::DoNotOptimize(generate_skeleton(p, 13, &stats));
  state.counters["nodes"] = static_cast<double>(stats.nodes);
  state.counters["structure"] = static_cast<double>(stats.structure_nodes);
  state.counters["peak_rss_MB"] = peak_rss_mb();
}

const bool kRegistered = [] {
  for (const char* file : {"graph_round_crown.toml", "graph_conifer.toml", "graph_willow.toml",
                           "graph_bush.toml", "graph_column.toml", "graph_umbrella.toml"})
    benchmark::RegisterBenchmark(("BM_GraphSpecies/" + std::string(file)).c_str(), BM_GraphSpecies,
                                 std::string(file))
        ->Unit(benchmark::kMillisecond);
  return true;
}();

}  // namespace

BENCHMARK_MAIN();
