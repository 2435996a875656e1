// The error of a render against a converged reference (issue 46's measure): the relative
// MSE of a channel, the mean over pixels of (x - ref)^2 / (ref^2 + 0.01 mean^2), mean the
// reference's mean of that channel; for luminance, each of R, G and B and every sensor band
// the image holds; and the mean samples per pixel the render took (its `spp` layer). Not a
// benchmark (prints once): usage image_error image.exr reference.exr
#include <cstdio>
#include <functional>
#include <stdexcept>
#include <string>

#include "renderer/output/image_output.h"

namespace {

using landsim::renderer::Film;
using Channel = std::function<double(const Film&, int, int)>;

double relative_mse(const Film& image, const Film& ref, const Channel& value) {
  double mean = 0.0;
  for (int y = 0; y < ref.height(); ++y)
    for (int x = 0; x < ref.width(); ++x) mean += value(ref, x, y);
  mean /= static_cast<double>(ref.pixel_count());
  double error = 0.0;
  for (int y = 0; y < ref.height(); ++y)
    for (int x = 0; x < ref.width(); ++x) {
      const double r = value(ref, x, y), d = value(image, x, y) - r;
      error += d * d / (r * r + 0.01 * mean * mean);
    }
  return error / static_cast<double>(ref.pixel_count());
}

double mean_spp(const Film& image) {
  double samples = 0.0;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x) samples += image.samples(x, y);
  return samples / static_cast<double>(image.pixel_count());
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: image_error image.exr reference.exr\n");
    return 2;
  }
  try {
    const Film a = landsim::renderer::read_exr(argv[1]);
    const Film ref = landsim::renderer::read_exr(argv[2]);
    if (a.width() != ref.width() || a.height() != ref.height()) {
      std::fprintf(stderr, "image_error: the images' sizes differ\n");
      return 2;
    }
    // Luminance first: the scripts read "rel_mse <luminance>".
    std::printf("rel_mse %.6g mean_spp %.2f",
                relative_mse(a, ref, [](const Film& f, int x, int y) { return f.luminance(x, y); }),
                mean_spp(a));
    const char* const kRgb[] = {"R", "G", "B"};
    for (int c = 0; c < 3; ++c)
      std::printf(" %s %.6g", kRgb[c], relative_mse(a, ref, [c](const Film& f, int x, int y) {
                    return static_cast<double>(f.rgb(x, y)[c]);
                  }));
    for (int b = 0; b < ref.band_count() && b < a.band_count(); ++b)
      std::printf(" %s %.6g", ref.band_name(b).c_str(),
                  relative_mse(a, ref, [b](const Film& f, int x, int y) {
                    return static_cast<double>(f.band(x, y, b));
                  }));
    std::printf("\n");
  } catch (const std::exception& e) {
    std::fprintf(stderr, "image_error: %s\n", e.what());
    return 2;
  }
  return 0;
}
