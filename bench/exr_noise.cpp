// Noise of a render, from two renders that differ only in their seed (bench/spectral.sh): the
// RMS of the two images' luminance difference over sqrt(2) (each image's own noise), relative
// to the mean luminance, over the pixels that are not sky, then the RMS itself and the mean
// (in the layer's unit: an image whose mean moved is compared at equal absolute error too);
// the same for each band layer both hold. Not a benchmark (prints once): usage exr_noise a.exr
// b.exr
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "renderer/output/image_output.h"

namespace {

using landsim::renderer::Film;

struct Noise {
  double rms = 0.0, mean = 0.0;
};

template <typename Value>
Noise noise(const Film& a, const Film& b, Value value) {
  double diff = 0.0, sum = 0.0;
  std::size_t n = 0;
  for (int y = 0; y < a.height(); ++y)
    for (int x = 0; x < a.width(); ++x) {
      if (a.object(x, y) == 0) continue;  // sky: noise-free, it would dilute the figure
      const double va = value(a, x, y), vb = value(b, x, y);
      diff += (va - vb) * (va - vb);
      sum += 0.5 * (va + vb);
      ++n;
    }
  if (n == 0 || sum <= 0.0) return {};
  return {std::sqrt(diff / static_cast<double>(n) / 2.0), sum / static_cast<double>(n)};
}

void print(const char* name, const Noise& n) {
  std::printf("%s %.4f rms %.4g mean %.4g\n", name, n.mean > 0.0 ? n.rms / n.mean : 0.0, n.rms,
              n.mean);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: exr_noise a.exr b.exr\n");
    return 2;
  }
  const Film a = landsim::renderer::read_exr(argv[1]);
  Film b = landsim::renderer::read_exr(argv[2]);
  if (a.width() != b.width() || a.height() != b.height() || !b.order_bands(a.band_names())) {
    std::fprintf(stderr, "exr_noise: the images differ in size or bands\n");
    return 2;
  }
  print("luminance", noise(a, b, [](const Film& f, int x, int y) { return f.luminance(x, y); }));
  for (int k = 0; k < a.band_count(); ++k)
    print(("band." + a.band_name(k)).c_str(),
          noise(a, b, [k](const Film& f, int x, int y) { return f.band(x, y, k); }));
  return 0;
}
