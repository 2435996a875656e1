#pragma once
// Image statistics the renderer tests share.
#include "renderer/output/film.h"

namespace landsim::test {

// Mean Rec. 709 luminance over every pixel.
inline double mean_luminance(const renderer::Film& f) {
  double sum = 0.0;
  for (int y = 0; y < f.height(); ++y)
    for (int x = 0; x < f.width(); ++x) sum += f.luminance(x, y);
  return sum / static_cast<double>(f.pixel_count());
}

}  // namespace landsim::test
