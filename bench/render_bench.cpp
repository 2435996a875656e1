// Render time of the embedded default scene (issue 2): 640 x 360, 16 spp, on 1 and 2
// threads, with the rays per second that implies (camera, bounce and shadow rays).
#include <benchmark/benchmark.h>

#include "renderer/transport/render.h"
#include "scenes/scenario/default_scenario.h"
#include "scenes/builder/scene_builder.h"

namespace {

using namespace landsim;

void BM_RenderDefaultScene(benchmark::State& state) {
  scenes::Scenario scenario = scenes::default_scenario();
  scenario.views[0].width = 640;
  scenario.views[0].height = 360;
  scenario.render.spp = 16;
  const renderer::Scene scene = scenes::build_scene(scenario);
  const renderer::Renderer renderer(scene);
  renderer::RenderOptions options;
  options.threads = static_cast<int>(state.range(0));
  std::uint64_t rays = 0;
  for (auto _ : state) {
    renderer::RenderStats stats;
    benchmark::DoNotOptimize(renderer.render(scene.views[0], options, &stats));
    rays += stats.rays;
  }
  state.counters["rays_per_second"] =
      benchmark::Counter(static_cast<double>(rays), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_RenderDefaultScene)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_LoadAndBuildDefaultScene(benchmark::State& state) {
  const scenes::Scenario scenario = scenes::default_scenario();
  for (auto _ : state) {
    const renderer::Scene scene = scenes::build_scene(scenario);
    benchmark::DoNotOptimize(renderer::Renderer(scene));
  }
}
BENCHMARK(BM_LoadAndBuildDefaultScene)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
