#include "renderer/transport/guide_training.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <vector>

#include "core/counter_rng.h"
#include "renderer/acceleration/stochastic_lod.h"
#include "renderer/transport/path_tracer.h"
#include "renderer/transport/render.h"

namespace landsim::renderer {
namespace {

// The training passes draw from their own streams: far from every render sample's.
constexpr std::uint64_t kTrainingSeed = 0x67756964696e6700ull;  // "guiding"
// Rows of pixels gathered together (one vector of records each, joined in order).
constexpr int kRowsPerChunk = 16;

// Whether `pixel` is among the `fraction` of pixels that take one sample more in pass `pass`:
// an evenly spread subset (the golden ratio's sequence over the pixel index), another for
// each pass.
bool takes_one_more(std::uint64_t pixel, int pass, double fraction) {
  const double x = static_cast<double>(pixel) * 0.6180339887498949 + 0.3819660112501051 * pass;
  return x - std::floor(x) < fraction;
}

struct PassResult {
  std::vector<GuideRecord> records;
  std::uint64_t paths = 0, rays = 0;
};

PassResult run_pass(const PathTracer& tracer, const Camera& camera, const View& view,
                    const RenderSettings& settings, tbb::task_arena& arena, int pass) {
  const double budget = guide_pass_budget(settings.guiding_training, settings.spp, pass);
  // Every pixel takes the budget's whole samples, an evenly spread share of them one more.
  const int whole = static_cast<int>(std::floor(budget));
  const double fraction = budget - whole;
  const int chunks = (view.height + kRowsPerChunk - 1) / kRowsPerChunk;
  std::vector<PassResult> parts(static_cast<std::size_t>(chunks));
  const std::uint64_t seed = settings.seed ^ (kTrainingSeed + static_cast<std::uint64_t>(pass));
  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<int>(0, chunks, 1), [&](const tbb::blocked_range<int>& r) {
      for (int c = r.begin(); c != r.end(); ++c) {
        PassResult& part = parts[static_cast<std::size_t>(c)];
        for (int y = c * kRowsPerChunk; y < std::min(view.height, (c + 1) * kRowsPerChunk); ++y)
          for (int x = 0; x < view.width; ++x) {
            const auto pixel =
                static_cast<std::uint64_t>(y) * static_cast<std::uint64_t>(view.width) +
                static_cast<std::uint64_t>(x);
            const int samples = whole + (takes_one_more(pixel, pass, fraction) ? 1 : 0);
            const std::uint32_t mask = pixel_ray_mask(pixel);
            for (int s = 0; s < samples; ++s) {
              const CounterRng rng(seed, pixel, static_cast<std::uint64_t>(s), settings.sampler);
              const std::optional<Ray> ray = sample_ray(camera, rng, x, y, false);
              if (!ray) continue;
              part.rays += tracer.train(*ray, rng, mask, part.records).rays;
              ++part.paths;
            }
          }
      }
    });
  });
  PassResult all;
  std::size_t total = 0;
  for (const PassResult& p : parts) total += p.records.size();
  all.records.reserve(total);
  for (PassResult& p : parts) {
    all.records.insert(all.records.end(), p.records.begin(), p.records.end());
    all.paths += p.paths;
    all.rays += p.rays;
    p.records = {};
  }
  return all;
}

}  // namespace

double guide_pass_budget(double share, int spp, int pass) {
  constexpr double kWhole = (1 << kGuideTrainingPasses) - 1;  // 1 + 2 + 4
  return share * spp * static_cast<double>(1 << pass) / kWhole;
}

std::shared_ptr<const GuidingField> train_guiding(PathTracer& tracer, const Camera& camera,
                                                  const View& view, const RenderSettings& settings,
                                                  int threads, GuideTrainingStats* stats) {
  const auto start = std::chrono::steady_clock::now();
  tbb::task_arena arena(threads > 0 ? threads : tbb::task_arena::automatic);
  std::shared_ptr<const GuidingField> field;
  GuideTrainingStats totals;
  tracer.guide_by(nullptr);
  for (int pass = 0; pass < kGuideTrainingPasses; ++pass) {
    PassResult result = run_pass(tracer, camera, view, settings, arena, pass);
    totals.paths += result.paths;
    totals.rays += result.rays;
    totals.records += result.records.size();
    field = std::make_shared<const GuidingField>(std::move(result.records));
    tracer.guide_by(field);  // the next pass, and then the render, sample by it
  }
  totals.regions = field->region_count();
  totals.directional_nodes = field->directional_nodes();
  totals.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (stats != nullptr) *stats = totals;
  return field;
}

}  // namespace landsim::renderer
