// The sensor's cost per image (issue 43, docs/PERFORMANCE.md "Sensor"): at 1920 x 1080, one
// channel through the optics (FFT) and the digitiser, and one image's downwelling irradiance
// (the sky's hemisphere); against the million-tree render's minutes, and the default scene's
// 640 x 360 x 16 spp render (render_bench) for scale.
#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

#include "renderer/atmosphere/downwelling.h"
#include "renderer/sensor/digitiser.h"
#include "renderer/sensor/optics.h"

namespace {

using namespace landsim;

constexpr int kWidth = 1920, kHeight = 1080;

// A textured photon image: every frequency the optics touch.
std::vector<float> photon_image() {
  std::vector<float> image(static_cast<std::size_t>(kWidth) * kHeight);
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x)
      image[static_cast<std::size_t>(y) * kWidth + x] =
          static_cast<float>(1e19 * (1.5 + std::sin(0.37 * x) * std::cos(0.21 * y)));
  return image;
}

void BM_OpticsOneChannel(benchmark::State& state) {
  renderer::SensorModel m;
  m.blur_sigma_um = 2.0;
  const std::vector<float> source = photon_image();
  for (auto _ : state) {
    std::vector<float> plane = source;
    renderer::apply_optics(plane, kWidth, kHeight, 550.0, m);
    benchmark::DoNotOptimize(plane.data());
  }
}
BENCHMARK(BM_OpticsOneChannel)->Unit(benchmark::kMillisecond);

void BM_DigitiseOneChannel(benchmark::State& state) {
  renderer::SensorModel m;
  const std::vector<float> plane = photon_image();
  for (auto _ : state)
    benchmark::DoNotOptimize(renderer::digitise(plane, kWidth, kHeight, 0.001, m, "bench", 0));
}
BENCHMARK(BM_DigitiseOneChannel)->Unit(benchmark::kMillisecond);

void BM_DownwellingIrradiance(benchmark::State& state) {
  renderer::Scene scene;
  scene.sun.direction = normalize(Vec3{0.3, -0.6, 0.7});
  scene.haze.enabled = true;
  for (auto _ : state) benchmark::DoNotOptimize(renderer::downwelling_irradiance(scene, 100.0));
}
BENCHMARK(BM_DownwellingIrradiance)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
