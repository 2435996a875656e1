// Rays per second of landsim's path tracer on the default scene (trees, grass, Preetham sky)
// against Embree's raw trace rate on exactly the same rays (issue 6): the paths are traced
// once with every ray recorded, then the recorded rays are traced again with rtcIntersect1 /
// rtcOccluded1 alone. 320 x 180, 16 spp, 2 threads.
#include <benchmark/benchmark.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <atomic>
#include <chrono>

#include "renderer/camera.h"
#include "renderer/detail/ray_recorder.h"
#include "renderer/embree_scene.h"
#include "renderer/path_tracer.h"
#include "scenes/default_scenario.h"
#include "scenes/scene_builder.h"

namespace {

using namespace landsim;

void BM_TraceRateAgainstEmbree(benchmark::State& state) {
  scenes::Scenario scenario = scenes::default_scenario();
  scenario.views[0].width = 320;
  scenario.views[0].height = 180;
  const renderer::Scene scene = scenes::build_scene(scenario);
  const renderer::View& view = scene.views[0];
  const renderer::EmbreeScene embree(scene, &view);
  const renderer::PathTracer tracer(scene, embree);
  const renderer::Camera camera(view);
  const int threads = 2;
  double path_seconds = 0.0, raw_seconds = 0.0;
  std::size_t ray_count = 0;
  for (auto _ : state) {
    // Pass 1: the renderer's rate (not recording: recording would slow it).
    tbb::task_arena arena(threads);
    std::atomic<std::uint64_t> rays{0};
    const auto trace_all = [&] {
      arena.execute([&] {
        tbb::parallel_for(
            tbb::blocked_range<int>(0, view.height), [&](const tbb::blocked_range<int>& r) {
              std::uint64_t local = 0;
              for (int y = r.begin(); y != r.end(); ++y) {
                for (int x = 0; x < view.width; ++x) {
                  for (int s = 0; s < scene.settings.spp; ++s) {
                    const CounterRng rng(scene.settings.seed,
                                         static_cast<std::uint64_t>(y * view.width + x),
                                         static_cast<std::uint64_t>(s));
                    local += tracer
                                 .trace(camera.ray(static_cast<float>(x) + rng.uniform(0),
                                                   static_cast<float>(y) + rng.uniform(1)),
                                        rng)
                                 .rays;
                  }
                }
              }
              rays += local;
            });
      });
    };
    const auto start = std::chrono::steady_clock::now();
    trace_all();
    path_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    // Pass 2: the same paths, recording every ray; then Embree alone on them.
    std::vector<renderer::detail::RecordedRay> all;
    {
      const renderer::detail::RayRecorder recorder(embree);
      trace_all();
      all = recorder.rays();
    }
    ray_count = all.size();
    raw_seconds = renderer::detail::RayRecorder::trace_raw(embree, all, threads);
    state.SetIterationTime(path_seconds);
  }
  state.counters["rays"] = static_cast<double>(ray_count);
  state.counters["landsim_rays_per_s"] = static_cast<double>(ray_count) / path_seconds;
  state.counters["embree_raw_rays_per_s"] = static_cast<double>(ray_count) / raw_seconds;
  state.counters["ratio"] = raw_seconds / path_seconds;
}
BENCHMARK(BM_TraceRateAgainstEmbree)->Unit(benchmark::kMillisecond)->UseManualTime()->Iterations(1);

}  // namespace

BENCHMARK_MAIN();
