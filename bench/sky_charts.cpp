// The sky models as documentation sees them (docs/ATMOSPHERE.md); not a benchmark.
//   sky_charts chart OUT.png      sky domes at sun elevations 5, 20, 45, 70 degrees (columns)
//                                 and turbidities 2, 4, 8 (rows), both models side by side
//   sky_charts horizon-table      the horizon's chromaticity (view elevation 4 degrees, three
//                                 azimuths from the sun) for both models, with its CIE 1960
//                                 uv distance from the daylight locus, as a markdown table
//   sky_charts illuminance        global horizontal illuminance (sun + sky), both models
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include "renderer/atmosphere/sky.h"
#include "renderer/output/exposure.h"
#include "renderer/output/film.h"
#include "renderer/output/image_output.h"
#include "renderer/spectra/colour_matching.h"

namespace {

using namespace landsim;
using renderer::SkyKind;

constexpr double kDeg = std::numbers::pi / 180.0;
constexpr Vec3f kGroundAlbedo{0.18f, 0.17f, 0.12f};  // the terrain's default

Vec3 toward(double elevation_deg, double azimuth_deg) {
  const double el = elevation_deg * kDeg, az = azimuth_deg * kDeg;
  return {std::sin(az) * std::cos(el), std::cos(az) * std::cos(el), std::sin(el)};
}

struct SkyAndSun {
  renderer::Sky sky;
  renderer::Sun sun;
};

SkyAndSun setting(SkyKind kind, double sun_elevation, double turbidity) {
  SkyAndSun s;
  s.sky.model = kind;
  s.sky.turbidity = turbidity;
  s.sun.direction = toward(sun_elevation, 180.0);  // in the south
  s.sun.irradiance = renderer::sun_irradiance(s.sky, sun_elevation, s.sun.angular_radius);
  return s;
}

const char* name_of(SkyKind kind) {
  return kind == SkyKind::hosek_wilkie ? "Hosek-Wilkie" : "Preetham";
}

// One dome: an equidistant fisheye (radius proportional to the zenith angle), north up, the
// sun below the centre; exposed on its own (key 0.18) so every sky's colours show.
void draw_dome(renderer::Film& film, int x0, int y0, int size, const renderer::SkyModel& sky) {
  renderer::Film dome(size, size);
  const double r = 0.5 * size;
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const double dx = (x + 0.5 - r) / r, dy = (r - y - 0.5) / r;
      const double rho = std::hypot(dx, dy);
      if (rho > 1.0) continue;
      const double zenith = rho * 0.5 * std::numbers::pi;
      const double azimuth = std::atan2(dx, dy);  // clockwise from north (up)
      const Vec3 d{std::sin(zenith) * std::sin(azimuth), std::sin(zenith) * std::cos(azimuth),
                   std::cos(zenith)};
      const Vec3f c = sky.radiance(Vec3f(d));
      auto& rgb = dome.rgb_data();
      const std::size_t i = 3 * (static_cast<std::size_t>(y) * size + x);
      rgb[i] = c.x;
      rgb[i + 1] = c.y;
      rgb[i + 2] = c.z;
    }
  // The key over the dome's own pixels (the corners outside it are not sky).
  double log_sum = 0.0;
  int inside = 0;
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x)
      if (std::hypot((x + 0.5 - r) / r, (r - y - 0.5) / r) <= 1.0) {
        log_sum += std::log(std::max(1e-4, static_cast<double>(dome.luminance(x, y))));
        ++inside;
      }
  const double gain = renderer::kExposureKey / std::exp(log_sum / inside);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const Vec3f c = dome.rgb(x, y);
      auto& rgb = film.rgb_data();
      const std::size_t i = 3 * (static_cast<std::size_t>(y0 + y) * film.width() + x0 + x);
      rgb[i] = static_cast<float>(c.x * gain);
      rgb[i + 1] = static_cast<float>(c.y * gain);
      rgb[i + 2] = static_cast<float>(c.z * gain);
    }
}

int chart(const std::string& out) {
  const double elevations[] = {5.0, 20.0, 45.0, 70.0};
  const double turbidities[] = {2.0, 4.0, 8.0};
  constexpr int kDome = 110, kGap = 8, kTop = 40, kLeft = 50;
  const int half = 4 * (kDome + kGap);
  renderer::Film film(kLeft + 2 * half + kGap, kTop + 3 * (kDome + kGap) + 30);
  std::vector<renderer::ImageLabel> labels;
  int model_index = 0;
  for (SkyKind kind : {SkyKind::hosek_wilkie, SkyKind::preetham}) {
    const int x_base = kLeft + model_index++ * (half + kGap);
    labels.push_back({x_base, 26, name_of(kind)});
    for (int col = 0; col < 4; ++col) {
      labels.push_back({x_base + col * (kDome + kGap) + 20, kTop + 3 * (kDome + kGap) + 4,
                        fmt::format("sun {:g} deg", elevations[col])});
      for (int row = 0; row < 3; ++row) {
        const SkyAndSun s = setting(kind, elevations[col], turbidities[row]);
        const renderer::SkyModel sky(s.sky, s.sun, kGroundAlbedo, renderer::SpectralGrid{});
        draw_dome(film, x_base + col * (kDome + kGap), kTop + row * (kDome + kGap), kDome, sky);
      }
    }
  }
  for (int row = 0; row < 3; ++row)
    labels.push_back(
        {4, kTop + row * (kDome + kGap) + kDome / 2, fmt::format("T {:g}", turbidities[row])});
  // The domes are already exposed: EV100 -log2(1.2) is a gain of 1.
  renderer::write_preview_png(film, out, -std::log2(1.2), labels);
  return 0;
}

int horizon_table() {
  std::printf(
      "| sun elevation | turbidity | azimuth from sun | Hosek-Wilkie x, y | uv distance | "
      "Preetham x, y | uv distance |\n|---|---|---|---|---|---|---|\n");
  for (double elevation : {10.0, 30.0, 50.0, 70.0})
    for (double turbidity : {2.0, 4.0, 6.0})
      for (double azimuth : {45.0, 90.0, 180.0}) {
        std::printf("| %g | %g | %g |", elevation, turbidity, azimuth);
        for (SkyKind kind : {SkyKind::hosek_wilkie, SkyKind::preetham}) {
          const SkyAndSun s = setting(kind, elevation, turbidity);
          const renderer::SkyModel sky(s.sky, s.sun, kGroundAlbedo, renderer::SpectralGrid{});
          // The sun is in the south (azimuth 180); this view is `azimuth` degrees from it.
          const Vec3 c(sky.radiance(Vec3f(toward(4.0, 180.0 + azimuth))));
          const renderer::Chromaticity xy = renderer::chromaticity_of(renderer::rec709_to_xyz(c));
          std::printf(" %.4f, %.4f | %+.4f |", xy.x, xy.y, renderer::daylight_locus_distance(xy));
        }
        std::printf("\n");
      }
  return 0;
}

int illuminance() {
  std::printf(
      "| model | sun elevation | turbidity | sun (horizontal), lux | sky, lux | global, lux |\n"
      "|---|---|---|---|---|---|\n");
  for (SkyKind kind : {SkyKind::hosek_wilkie, SkyKind::preetham})
    for (double elevation : {10.0, 30.0, 60.0})
      for (double turbidity : {2.5, 4.0}) {
        const SkyAndSun s = setting(kind, elevation, turbidity);
        const renderer::SkyModel sky(s.sky, s.sun, kGroundAlbedo, renderer::SpectralGrid{});
        const double sun =
            renderer::rec709_luminance(Vec3(s.sun.irradiance)) * std::sin(elevation * kDeg);
        const double diffuse = renderer::rec709_luminance(Vec3(sky.horizontal_irradiance()));
        std::printf("| %s | %g | %g | %.0f | %.0f | %.0f |\n", name_of(kind), elevation, turbidity,
                    sun, diffuse, sun + diffuse);
      }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string mode = argc > 1 ? argv[1] : "";
  if (mode == "chart" && argc == 3) return chart(argv[2]);
  if (mode == "horizon-table" && argc == 2) return horizon_table();
  if (mode == "illuminance" && argc == 2) return illuminance();
  std::fprintf(stderr, "usage: sky_charts chart OUT.png | horizon-table | illuminance\n");
  return 2;
}
