#pragma once
// Image statistics the renderer tests share.
#include <cstring>

#include "renderer/output/film.h"

namespace landsim::test {

// Mean Rec. 709 luminance over every pixel.
inline double mean_luminance(const renderer::Film& f) {
  double sum = 0.0;
  for (int y = 0; y < f.height(); ++y)
    for (int x = 0; x < f.width(); ++x) sum += f.luminance(x, y);
  return sum / static_cast<double>(f.pixel_count());
}

// Whether two films hold the same RGB, bit for bit (the determinism tests' check).
inline bool same_rgb_bits(const renderer::Film& a, const renderer::Film& b) {
  return a.rgb_data().size() == b.rgb_data().size() &&
         std::memcmp(a.rgb_data().data(), b.rgb_data().data(),
                     a.rgb_data().size() * sizeof(float)) == 0;
}

}  // namespace landsim::test
