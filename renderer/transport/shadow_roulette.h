#pragma once
// Russian roulette of shadow rays by their contribution (docs/PERFORMANCE.md "Forest
// scale"). Before a shadow ray is traced, what it would add to the pixel if unoccluded is
// known; a ray whose contribution (largest component) is below `threshold` is traced with
// probability contribution / threshold and, when traced, weighted by its inverse. The
// estimate stays unbiased and no traced ray adds more than `threshold`, so the noise it adds
// is bounded while the many faint rays deep in a path (or in dark foliage) mostly go
// untraced.
namespace landsim::renderer {

struct ShadowRoulette {
  float threshold = 0.0f;  // 0: every ray is traced
  float u = 0.0f;          // this decision's uniform number in [0, 1)
};

// The weight for a ray of `contribution`: 1 when it is traced outright, 1/q when it survives
// with probability q, 0 when it is not traced (always, when it would add nothing).
inline float shadow_roulette_weight(float contribution, const ShadowRoulette& r) {
  // Nothing to add is never traced, whatever the threshold (with none, a black sky's rays
  // were: one wasted ray at every vertex of a benchmark lit by the sun alone).
  if (contribution <= 0.0f) return 0.0f;
  if (contribution >= r.threshold) return 1.0f;
  const float q = contribution / r.threshold;
  return r.u < q ? 1.0f / q : 0.0f;
}

}  // namespace landsim::renderer
