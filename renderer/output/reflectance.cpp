#include "renderer/output/reflectance.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <string>

#include "renderer/atmosphere/downwelling.h"
#include "renderer/output/image_output.h"
#include "renderer/spectra/colour_matching.h"
#include "renderer/spectra/spectral_colour.h"

namespace landsim::renderer {
namespace {

// pi x plane / e, 0 where e is 0; at least 0 (what rounding takes below it).
std::vector<float> reflectance_plane(std::size_t n, double e,
                                     const std::function<double(std::size_t)>& radiance) {
  std::vector<float> plane(n, 0.0f);
  if (e > 0.0)
    for (std::size_t i = 0; i < n; ++i)
      plane[i] = static_cast<float>(std::max(0.0, std::numbers::pi * radiance(i) / e));
  return plane;
}

}  // namespace

ImageIrradiance image_irradiance(const Scene& scene, const Film& film) {
  const Vec3f centre = film.position(film.width() / 2, film.height() / 2);
  ImageIrradiance out;
  out.height = std::isfinite(centre.z) ? centre.z : scene.haze.base_height;
  const Downwelling d = downwelling_irradiance(scene, out.height);
  const Spectrum total = d.total();
  out.rgb = spectrum_to_rgb(total);
  out.xyz = spectrum_to_xyz(total);
  out.direct_rgb = spectrum_to_rgb(d.direct);
  out.diffuse_rgb = spectrum_to_rgb(d.diffuse);
  for (const SpectralBand& b : scene.bands) {
    double e = 0.0;
    for (int k = 0; k < kSpectrumBins; ++k) e += static_cast<double>(b.weight[k]) * total[k];
    out.layers.push_back(e);
  }
  return out;
}

void add_reflectance(Film& film, const ImageIrradiance& e) {
  const std::size_t n = film.pixel_count();
  const std::vector<float>& rgb = film.rgb_data();
  const auto xyz = [&](std::size_t i) {
    return rec709_to_xyz(Vec3(rgb[3 * i], rgb[3 * i + 1], rgb[3 * i + 2]));
  };
  for (int c = 0; c < 3; ++c) {
    std::vector<float> r = reflectance_plane(n, e.xyz[c], [&](std::size_t i) { return xyz(i)[c]; });
    film.add_band(std::string("reflectance.") + "XYZ"[c], std::move(r));
  }
  const int layers = std::min(film.band_count(), static_cast<int>(e.layers.size()));
  for (int b = 0; b < layers; ++b) {
    // Computed before add_band, which may move the film's planes.
    std::vector<float> r = reflectance_plane(n, e.layers[static_cast<std::size_t>(b)],
                                             [&](std::size_t i) { return film.band_data(b)[i]; });
    film.add_band("reflectance." + band_layer(film.band_name(b)), std::move(r));
  }
}

}  // namespace landsim::renderer
