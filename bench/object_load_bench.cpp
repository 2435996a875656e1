// Scene objects (issue 21): the load time of a 1 M-triangle mesh through Assimp (binary PLY
// and OBJ text, written once into a temporary folder), and a whole scene build with that
// mesh placed on a small terrain (reading, axes, placement's ground probes) against the same
// build without it.
#include <benchmark/benchmark.h>
#include <fmt/format.h>
#include <fmt/os.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <vector>

#include "scenes/builder/mesh_io.h"
#include "scenes/scenario/scenario.h"
#include "scenes/builder/scene_builder.h"

namespace {

using namespace landsim;

// A wavy sheet of kSide x kSide quads, two triangles each: 2 kSide^2 = 1.03 M triangles,
// 10 m across, y up.
constexpr int kSide = 718;

std::filesystem::path folder() {
  static const std::filesystem::path dir = [] {
    const auto d = std::filesystem::temp_directory_path() / "landsim-object-bench";
    std::filesystem::create_directories(d);
    return d;
  }();
  return dir;
}

float height(int i, int j) {
  return 0.2f * std::sin(0.05f * static_cast<float>(i)) * std::cos(0.07f * static_cast<float>(j)) +
         0.5f;
}

// Coordinate k of the sheet's lattice, metres.
float coordinate(int k) { return 10.0f * static_cast<float>(k) / kSide - 5.0f; }

std::filesystem::path ply() {
  const auto path = folder() / "sheet.ply";
  if (std::filesystem::exists(path)) return path;
  const int n = kSide + 1;
  std::ofstream out(path, std::ios::binary);
  out << "ply\nformat binary_little_endian 1.0\nelement vertex " << n * n
      << "\nproperty float x\nproperty float y\nproperty float z\nelement face "
      << 2 * kSide * kSide << "\nproperty list uchar int vertex_indices\nend_header\n";
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const float v[3] = {coordinate(i), height(i, j), coordinate(j)};
      out.write(reinterpret_cast<const char*>(v), sizeof v);
    }
  for (int i = 0; i < kSide; ++i)
    for (int j = 0; j < kSide; ++j) {
      const std::int32_t a = i * n + j, b = a + 1, c = a + n, d = c + 1;
      const std::uint8_t three = 3;
      const std::int32_t tris[6] = {a, b, d, a, d, c};
      for (int k = 0; k < 2; ++k) {
        out.write(reinterpret_cast<const char*>(&three), 1);
        out.write(reinterpret_cast<const char*>(tris + 3 * k), 12);
      }
    }
  return path;
}

std::filesystem::path obj() {
  const auto path = folder() / "sheet.obj";
  if (std::filesystem::exists(path)) return path;
  const int n = kSide + 1;
  auto out = fmt::output_file(path.string());
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      out.print("v {:.5f} {:.5f} {:.5f}\n", coordinate(i), height(i, j), coordinate(j));
  for (int i = 0; i < kSide; ++i)
    for (int j = 0; j < kSide; ++j) {
      const int a = i * n + j + 1, b = a + 1, c = a + n, d = c + 1;
      out.print("f {} {} {}\nf {} {} {}\n", a, b, d, a, d, c);
    }
  return path;
}

void read(benchmark::State& state, const std::filesystem::path& path) {
  std::size_t triangles = 0;
  for (auto _ : state) {
    scenes::MeshData mesh;
    std::string error;
    if (!scenes::mesh_io().read(path.string(), mesh, error)) state.SkipWithError(error.c_str());
    triangles = mesh.indices.size() / 3;
  }
  state.counters["triangles"] = static_cast<double>(triangles);
}

void BM_ReadBinaryPly(benchmark::State& state) { read(state, ply()); }
BENCHMARK(BM_ReadBinaryPly)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_ReadObjText(benchmark::State& state) { read(state, obj()); }
BENCHMARK(BM_ReadObjText)->Unit(benchmark::kMillisecond)->UseRealTime();

// The volcano with the sheet placed on it (Arg 1) or without (Arg 0).
void BM_BuildSceneWithObject(benchmark::State& state) {
  const std::string dem = std::string(LANDSIM_SOURCE_DIR) + "/data/terrain/volcano.asc";
  std::string text = "[terrain]\nelevation = \"" + dem +
                     "\"\n[sun]\nelevation = 40\nazimuth = 200\n[[views]]\nname = \"v\"\n"
                     "position = [300.0, 300.0, 400.0]\ntarget = [320.0, 320.0, 200.0]\n";
  if (state.range(0) != 0)
    text += "[[objects]]\nname = \"sheet\"\nfile = \"" + ply().string() +
            "\"\nposition = [300.0, 400.0]\nalign_to_ground = true\n";
  const auto file = folder() / "scenario.toml";
  std::ofstream(file) << text;
  const scenes::Scenario scenario = scenes::load_scenario(file);
  std::size_t triangles = 0;
  for (auto _ : state) {
    const renderer::Scene scene = scenes::build_scene(scenario);
    triangles = scene.object_prototypes.empty() ? 0 : scene.object_prototypes[0].triangle_count();
  }
  state.counters["triangles"] = static_cast<double>(triangles);
}
BENCHMARK(BM_BuildSceneWithObject)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
