#pragma once
// For benchmarks (bench/trace_rate_bench.cpp), not for rendering: records every ray an
// EmbreeScene traces while a recorder is attached, and traces such rays again with Embree
// alone (no shading), to measure how much of a render's time is Embree's.
#include <cstdint>
#include <vector>

#include "renderer/camera.h"

namespace landsim::renderer {
class EmbreeScene;
}

namespace landsim::renderer::detail {

struct RecordedRay {
  Ray ray;
  float t_far;
  std::uint32_t mask;  // the ray's mask (stochastic levels)
  bool occlusion;      // a shadow ray (rtcOccluded1) rather than a closest hit (rtcIntersect1)
};

class RayRecorder {
 public:
  // Records the rays `scene` traces until destroyed, one list per TBB worker (up to
  // `workers`). The scene must not be traced from elsewhere meanwhile.
  explicit RayRecorder(const EmbreeScene& scene, std::size_t workers = 64);
  ~RayRecorder();
  RayRecorder(const RayRecorder&) = delete;
  RayRecorder& operator=(const RayRecorder&) = delete;

  // Every ray recorded so far, worker by worker.
  std::vector<RecordedRay> rays() const;

  // Traces `rays` through `scene` with Embree alone on `threads` workers; returns seconds.
  static double trace_raw(const EmbreeScene& scene, const std::vector<RecordedRay>& rays,
                          int threads);

 private:
  const EmbreeScene& scene_;
  std::vector<std::vector<RecordedRay>> lists_;
};

}  // namespace landsim::renderer::detail
