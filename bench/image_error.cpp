// The error of a render against a converged reference (issue 46's measure): the relative
// MSE of luminance, the mean over pixels of (x - ref)^2 / (ref^2 + 0.01 mean^2), mean the
// reference's mean luminance; and the mean samples per pixel the render took (its `spp`
// layer). Not a benchmark (prints once): usage image_error image.exr reference.exr
#include <cstdio>
#include <stdexcept>

#include "renderer/output/image_output.h"

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: image_error image.exr reference.exr\n");
    return 2;
  }
  try {
    const landsim::renderer::Film a = landsim::renderer::read_exr(argv[1]);
    const landsim::renderer::Film ref = landsim::renderer::read_exr(argv[2]);
    if (a.width() != ref.width() || a.height() != ref.height()) {
      std::fprintf(stderr, "image_error: the images' sizes differ\n");
      return 2;
    }
    double mean = 0.0;
    for (int y = 0; y < ref.height(); ++y)
      for (int x = 0; x < ref.width(); ++x) mean += ref.luminance(x, y);
    mean /= static_cast<double>(ref.pixel_count());
    double error = 0.0, samples = 0.0;
    for (int y = 0; y < ref.height(); ++y)
      for (int x = 0; x < ref.width(); ++x) {
        const double r = ref.luminance(x, y), d = a.luminance(x, y) - r;
        error += d * d / (r * r + 0.01 * mean * mean);
        samples += a.samples(x, y);
      }
    const auto n = static_cast<double>(ref.pixel_count());
    std::printf("rel_mse %.6g mean_spp %.2f\n", error / n, samples / n);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "image_error: %s\n", e.what());
    return 2;
  }
  return 0;
}
