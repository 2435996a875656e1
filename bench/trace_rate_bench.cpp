// Rays per second of landsim's path tracer against Embree's raw trace rate on exactly the same
// rays (issues 6 and 18): the paths are traced once, then again with every ray recorded (and
// its mask: stochastic levels), then the recorded rays are traced with rtcIntersect1 /
// rtcOccluded1 alone. Default: the embedded scene at 320 x 180, 16 spp, 2 threads; or
//   trace_rate_bench --scenario FILE [--width W] [--height H] [--spp N] [--view NAME]
// e.g. the million-tree forest (bench/scenarios/kagwene_1m.toml) at 480 x 270, 2 spp.
#include <benchmark/benchmark.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <atomic>
#include <chrono>
#include <cstring>
#include <optional>
#include <string>

#include "renderer/acceleration/embree_scene.h"
#include "renderer/acceleration/stochastic_lod.h"
#include "renderer/camera.h"
#include "renderer/transport/detail/ray_recorder.h"
#include "renderer/transport/path_tracer.h"
#include "scenes/scenario/default_scenario.h"
#include "scenes/builder/scene_builder.h"

namespace {

using namespace landsim;

struct Config {
  std::string scenario;  // empty: the embedded default scene
  std::string view;
  int width = 320, height = 180, spp = 16;
};
Config g_config;

scenes::Scenario configured_scenario() {
  scenes::Scenario s = g_config.scenario.empty() ? scenes::default_scenario()
                                                 : scenes::load_scenario(g_config.scenario);
  std::size_t v = 0;
  for (std::size_t i = 0; i < s.views.size(); ++i)
    if (s.views[i].name == g_config.view) v = i;
  s.views = {s.views[v]};
  s.views[0].width = g_config.width;
  s.views[0].height = g_config.height;
  s.render.spp = g_config.spp;
  return s;
}

// Every pixel's samples as the renderer draws them (render.cpp's render_tile: the pixel's
// ray mask, the counter-based random numbers), on `threads` workers; returns rays traced.
std::uint64_t trace_view(const renderer::PathTracer& tracer, const renderer::View& view,
                         const renderer::RenderSettings& settings, int threads) {
  const renderer::Camera camera(view);
  tbb::task_arena arena(threads);
  std::atomic<std::uint64_t> rays{0};
  arena.execute([&] {
    tbb::parallel_for(
        tbb::blocked_range<int>(0, view.height), [&](const tbb::blocked_range<int>& r) {
          std::uint64_t local = 0;
          for (int y = r.begin(); y != r.end(); ++y) {
            for (int x = 0; x < view.width; ++x) {
              const auto pixel = static_cast<std::uint64_t>(y * view.width + x);
              const std::uint32_t mask = renderer::pixel_ray_mask(pixel);
              for (int s = 0; s < settings.spp; ++s) {
                const CounterRng rng(settings.seed, pixel, static_cast<std::uint64_t>(s));
                const renderer::Ray ray = *camera.ray(static_cast<float>(x) + rng.uniform(0),
                                                      static_cast<float>(y) + rng.uniform(1));
                local += tracer.trace(ray, rng, mask).rays;
              }
            }
          }
          rays += local;
        });
  });
  return rays.load();
}

void BM_TraceRateAgainstEmbree(benchmark::State& state) {
  const scenes::Scenario scenario = configured_scenario();
  const renderer::Scene scene = scenes::build_scene(scenario);
  const renderer::View& view = scene.views[0];
  const renderer::EmbreeScene embree(scene, &view);
  const renderer::PathTracer tracer(scene, embree);
  const int threads = 2;
  double path_seconds = 0.0, raw_seconds = 0.0, shadow_seconds = 0.0, closest_seconds = 0.0;
  std::size_t ray_count = 0, shadow_count = 0;
  for (auto _ : state) {
    // Pass 1: the renderer's rate (not recording: recording would slow it).
    const auto start = std::chrono::steady_clock::now();
    trace_view(tracer, view, scene.settings, threads);
    path_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    // Pass 2: the same paths, recording every ray; then Embree alone on them.
    std::vector<renderer::detail::RecordedRay> all;
    {
      const renderer::detail::RayRecorder recorder(embree);
      trace_view(tracer, view, scene.settings, threads);
      all = recorder.rays();
    }
    ray_count = all.size();
    raw_seconds = renderer::detail::RayRecorder::trace_raw(embree, all, threads);
    // Shadow rays (rtcOccluded1) and closest hits (rtcIntersect1) apart: which kind the
    // time goes to.
    std::vector<renderer::detail::RecordedRay> shadow, closest;
    for (const auto& r : all) (r.occlusion ? shadow : closest).push_back(r);
    shadow_seconds = renderer::detail::RayRecorder::trace_raw(embree, shadow, threads);
    closest_seconds = renderer::detail::RayRecorder::trace_raw(embree, closest, threads);
    shadow_count = shadow.size();
    state.SetIterationTime(path_seconds);
  }
  state.counters["rays"] = static_cast<double>(ray_count);
  state.counters["landsim_rays_per_s"] = static_cast<double>(ray_count) / path_seconds;
  state.counters["embree_raw_rays_per_s"] = static_cast<double>(ray_count) / raw_seconds;
  state.counters["ratio"] = raw_seconds / path_seconds;
  state.counters["shadow_rays"] = static_cast<double>(shadow_count);
  state.counters["embree_shadow_s"] = shadow_seconds;
  state.counters["embree_closest_s"] = closest_seconds;
}
BENCHMARK(BM_TraceRateAgainstEmbree)->Unit(benchmark::kMillisecond)->UseManualTime()->Iterations(1);

// Takes this benchmark's own options out of argv before Google Benchmark sees it.
void take_options(int& argc, char** argv) {
  int kept = 1;
  for (int i = 1; i < argc; ++i) {
    const auto value = [&](const char* name) -> std::optional<std::string> {
      if (std::strcmp(argv[i], name) != 0 || i + 1 >= argc) return std::nullopt;
      return std::string(argv[++i]);
    };
    if (auto v = value("--scenario"))
      g_config.scenario = *v;
    else if (auto w = value("--width"))
      g_config.width = std::stoi(*w);
    else if (auto h = value("--height"))
      g_config.height = std::stoi(*h);
    else if (auto n = value("--spp"))
      g_config.spp = std::stoi(*n);
    else if (auto name = value("--view"))
      g_config.view = *name;
    else
      argv[kept++] = argv[i];
  }
  argc = kept;
}

}  // namespace

int main(int argc, char** argv) {
  take_options(argc, argv);
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
