#pragma once
// One pass over the markers on every core: what each marker decides on its own (taken by a
// bud's occupancy, owned by a bud's cone), in marker order, so that what the caller then
// adds up in that order is the same bits on any number of cores.
#include <cstddef>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "core/vec3.h"

namespace landsim::trees::self_organizing {

template <typename T, typename Decide>
std::vector<T> per_marker(const std::vector<Vec3>& markers, T initial, Decide&& decide) {
  std::vector<T> out(markers.size(), initial);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, markers.size(), 4096),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      for (std::size_t i = r.begin(); i != r.end(); ++i)
                        out[i] = decide(markers[i]);
                    });
  return out;
}

}  // namespace landsim::trees::self_organizing
