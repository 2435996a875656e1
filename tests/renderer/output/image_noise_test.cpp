// An image's own error estimate (the manifest's `noise`): its sums by hand on a film of two
// pixels, and, on a rendered panel, the relative MSE it states against the one a converged
// reference of another seed shows (issue 46's measure, bench/image_error).
#include "renderer/output/image_noise.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "renderer/atmosphere/sky.h"
#include "renderer/transport/render.h"
#include "tests/renderer/test_scenes.h"

namespace landsim::renderer {
namespace {

TEST(ImageNoise, SumsThePixelsVariancesAsTheErrorMeasureDoes) {
  Film film(2, 1);
  film.set(0, 0, {10.0f, 10.0f, 10.0f}, {});  // grey: luminance 10
  film.set(1, 0, {30.0f, 30.0f, 30.0f}, {});
  film.set_luminance_variance(0, 0, 1.0f);
  film.set_luminance_variance(1, 0, 4.0f);
  film.set_samples(0, 0, 4);
  film.set_samples(1, 0, 8);
  const auto n = image_noise(film);
  ASSERT_TRUE(n);
  const double mean = 20.0;
  EXPECT_NEAR(n->relative_mse, 0.5 * (1.0 / (100.0 + 0.01 * mean * mean) + 4.0 / (900.0 + 4.0)),
              1e-6);
  EXPECT_NEAR(n->frame_relative_se, std::sqrt(5.0) / 2.0 / mean, 1e-6);
  EXPECT_NEAR(n->mean_spp, 6.0, 1e-12);
  // Of two pixels the lower (4 / 904 under 1 / 104) is the median and, by rank, the 95th.
  EXPECT_NEAR(n->pixel_relative_se_median, std::sqrt(4.0 / 904.0), 1e-6);
  EXPECT_NEAR(n->pixel_relative_se_p95, std::sqrt(4.0 / 904.0), 1e-6);
  // A pixel of one sample has no variance to tell: nothing is stated.
  film.set_samples(1, 0, 1);
  EXPECT_FALSE(image_noise(film));
}

// The relative MSE of `image` against `reference` (bench/image_error's measure).
double relative_mse(const Film& image, const Film& reference) {
  const double n = static_cast<double>(reference.pixel_count());
  double mean = 0.0, error = 0.0;
  for (int y = 0; y < reference.height(); ++y)
    for (int x = 0; x < reference.width(); ++x) mean += reference.luminance(x, y) / n;
  for (int y = 0; y < reference.height(); ++y)
    for (int x = 0; x < reference.width(); ++x) {
      const double r = reference.luminance(x, y), d = image.luminance(x, y) - r;
      error += d * d / (r * r + 0.01 * mean * mean) / n;
    }
  return error;
}

// A grey ground under sun and sky, seen obliquely (its sky light sampled, so every pixel has
// noise). With independent samples the error the image states of itself is the error it has
// against a converged reference of another seed; under the Sobol sampler (the default) its
// samples are stratified, their spread overstates its error, and the statement is a bound.
TEST(ImageNoise, TheStatedErrorIsTheErrorAgainstAReferenceOrABoundUnderSobol) {
  Scene s;
  s.ground.mesh = testing::flat_ground(1e4);
  s.ground.albedo = {0.3f, 0.3f, 0.3f};
  const double elevation = 25.0 * std::numbers::pi / 180.0;
  s.sun.direction = normalize(Vec3{0.4, -std::cos(elevation), std::sin(elevation)});
  s.sun.irradiance = sun_irradiance(s.sky, 25.0, s.sun.angular_radius);
  s.views.push_back({"v", {0.0, 0.0, 20.0}, {0.0, 60.0, 0.0}, 50.0, 24, 24});
  s.settings.spp = 512;
  s.settings.seed = 2;
  const Film reference = Renderer(s).render(s.views[0], {});
  s.settings.spp = 8;
  s.settings.seed = 1;
  for (const SampleSequence sampler : {SampleSequence::independent, SampleSequence::sobol}) {
    s.settings.sampler = sampler;
    const Film image = Renderer(s).render(s.views[0], {});
    const auto stated = image_noise(image);
    ASSERT_TRUE(stated);
    const double real = relative_mse(image, reference);
    std::printf("%s: relative MSE stated %.4g, against the reference %.4g\n",
                sampler == SampleSequence::sobol ? "sobol" : "independent", stated->relative_mse,
                real);
    ASSERT_GT(real, 0.0);
    if (sampler == SampleSequence::independent)
      EXPECT_NEAR(stated->relative_mse / real, 1.0, 0.3);
    else
      EXPECT_GT(stated->relative_mse, real);
  }
}

}  // namespace
}  // namespace landsim::renderer
