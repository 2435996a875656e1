// Measured-growth core (issue 10): generation time of the London plane at 10, 30 and 60
// years (growth, skeleton and mesh, one thread); and, printed before the benchmarks, how the
// model matches the 27 London planes measured in Modesto: the model's height and crown
// diameter (measured on its geometry) at each tree's age against the tree's.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "trees/measured_growth/dimensions.h"
#include "trees/species.h"

namespace {

using namespace landsim::trees;

const std::filesystem::path kSource(LANDSIM_SOURCE_DIR);

Species london_plane() { return load_species(kSource / "data/species/london_plane.toml"); }

void BM_LondonPlane(benchmark::State& state) {
  const Species s = london_plane();
  const double age = static_cast<double>(state.range(0));
  Tree tree;
  for (auto _ : state) tree = generate(s, {.seed = 1, .age = age});
  state.counters["stems"] =
      static_cast<double>(tree.stats.stems_per_level[0] + tree.stats.stems_per_level[1] +
                          tree.stats.stems_per_level[2] + tree.stats.stems_per_level[3]);
  state.counters["leaves"] = tree.stats.leaves;
}
BENCHMARK(BM_LondonPlane)->Arg(10)->Arg(30)->Arg(60)->Unit(benchmark::kMillisecond);

// The Modesto trees: age, height, average crown diameter (columns 4, 6 and 11, from 0).
void compare_with_measured_trees() {
  std::ifstream in(kSource / "data/allometry/modesto_london_plane_trees.csv");
  const Species s = london_plane();
  const auto& a = std::get<measured_growth::Parameters>(s.parameters).allometry;
  std::string line;
  std::getline(in, line);  // header
  std::printf(
      "Modesto London planes: age | height m: tree, model, equation | crown diameter m: "
      "tree, model, equation\n");
  double model_h = 0, model_cd = 0, eq_h = 0, eq_cd = 0;
  int n = 0;
  while (std::getline(in, line)) {
    // Quoted "Modesto, CA" holds a comma: drop the quotes' content first.
    const auto q1 = line.find('"'), q2 = line.find('"', q1 + 1);
    if (q1 != std::string::npos) line.erase(q1, q2 - q1 + 1);
    std::vector<std::string> c;
    std::stringstream ss(line);
    for (std::string cell; std::getline(ss, cell, ',');) c.push_back(cell);
    const double age = std::stod(c[4]), height = std::stod(c[6]), crown = std::stod(c[11]);
    const auto d = measured_growth::measure(generate(s, {.seed = 1, .age = age}).geometry);
    std::printf("%5.0f | %5.1f %5.1f %5.1f | %5.1f %5.1f %5.1f\n", age, height, d.height_m,
                a.f_height(age), crown, d.crown_diameter_m, a.f_crown_diameter(age));
    model_h += std::abs(d.height_m - height) / height;
    model_cd += std::abs(d.crown_diameter_m - crown) / crown;
    eq_h += std::abs(a.f_height(age) - height) / height;
    eq_cd += std::abs(a.f_crown_diameter(age) - crown) / crown;
    ++n;
  }
  std::printf(
      "mean absolute error over %d trees: model height %.1f %%, crown diameter %.1f %%; "
      "equations height %.1f %%, crown diameter %.1f %%\n\n",
      n, 100 * model_h / n, 100 * model_cd / n, 100 * eq_h / n, 100 * eq_cd / n);
}

}  // namespace

int main(int argc, char** argv) {
  compare_with_measured_trees();
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
