#include "renderer/output/atmosphere_layers.h"

#include <algorithm>
#include <array>
#include <numbers>

#include "renderer/output/illumination_layers.h"
#include "renderer/output/image_output.h"
#include "renderer/scene.h"
#include "renderer/spectra/spectral_colour.h"
#include "renderer/transport/integrator.h"

namespace landsim::renderer {
namespace {

static_assert(kMaxLayers == kMaxBands + kAtmosphereParts * (3 + kMaxBands) + kIlluminationLayers,
              "a sample's planes (renderer/transport/integrator.h) hold every part");

constexpr std::array<const char*, kAtmosphereParts> kPartNames = {"path", "transmittance",
                                                                  "surface", "direct", "diffuse"};
// Colour in CIE X, Y, Z: the parts are divided by one another (transmittance, reflectance),
// which Rec. 709's R, G, B, negative for saturated colours, would take below zero.
constexpr std::array<const char*, 3> kXyz = {"X", "Y", "Z"};
constexpr const char* kSurfacePrefix = "atmosphere.surface.";
constexpr const char* kReflectancePrefix = "atmosphere.reflectance.";

const Spectrum& part_of(const AtmosphereSample& s, int part) {
  const std::array<const Spectrum*, kAtmosphereParts> parts = {&s.path, &s.transmittance,
                                                               &s.through, &s.direct, &s.diffuse};
  return *parts[static_cast<std::size_t>(part)];
}

}  // namespace

std::vector<std::string> atmosphere_layer_names(const std::vector<SpectralBand>& bands) {
  std::vector<std::string> names;
  for (const char* part : kPartNames) {
    const std::string prefix = std::string("atmosphere.") + part + ".";
    for (const char* c : kXyz) names.push_back(prefix + c);
    for (const SpectralBand& b : bands) names.push_back(prefix + band_layer(b.name));
  }
  return names;
}

int atmosphere_layer(AtmospherePart part, int channel, int band_count) {
  return band_count + static_cast<int>(part) * (3 + band_count) + channel;
}

void atmosphere_layer_values(const AtmosphereSample& s, const std::vector<SpectralBand>& bands,
                             float* layers) {
  const auto n = static_cast<int>(bands.size());
  // The transmittance of an equal-energy spectrum in each channel and band.
  static const Vec3f white = spectrum_to_xyz(Spectrum::constant(1.0f));
  for (int part = 0; part < kAtmosphereParts; ++part) {
    const Spectrum& x = part_of(s, part);
    const bool transmittance = part == static_cast<int>(AtmospherePart::transmittance);
    float* out = layers + part * (3 + n);
    const Vec3f xyz = spectrum_to_xyz(x);
    for (int c = 0; c < 3; ++c)
      out[c] = !transmittance ? xyz[c] : white[c] > 0.0f ? xyz[c] / white[c] : 0.0f;
    for (int b = 0; b < n; ++b) {
      const Spectrum& w = bands[static_cast<std::size_t>(b)].weight;
      const float sum = dot(w, x), weight = dot(w, Spectrum::constant(1.0f));
      out[3 + b] = !transmittance ? sum : weight > 0.0f ? sum / weight : 0.0f;
    }
  }
}

void finish_atmosphere_layers(Film& film, int band_count) {
  const std::size_t pixels = film.pixel_count();
  const int channels = 3 + band_count;
  std::vector<std::pair<std::string, std::vector<float>>> added;
  for (int c = 0; c < channels; ++c) {
    std::vector<float>& surface =
        film.band_data(atmosphere_layer(AtmospherePart::surface, c, band_count));
    const std::vector<float>& t =
        film.band_data(atmosphere_layer(AtmospherePart::transmittance, c, band_count));
    const std::vector<float>& direct =
        film.band_data(atmosphere_layer(AtmospherePart::direct, c, band_count));
    const std::vector<float>& diffuse =
        film.band_data(atmosphere_layer(AtmospherePart::diffuse, c, band_count));
    std::vector<float> r(pixels, 0.0f);
    for (std::size_t i = 0; i < pixels; ++i) {
      // The surface's light as it left the surface: what arrived over what the air let through.
      surface[i] = t[i] > 0.0f ? surface[i] / t[i] : 0.0f;
      const float e = direct[i] + diffuse[i];
      // Held at 0 where a control variate's noise takes a pixel's estimate below (a few
      // pixels at low samples): a reflectance factor is never negative.
      if (e > 0.0f) r[i] = std::max(0.0f, std::numbers::pi_v<float> * surface[i] / e);
    }
    const std::string& name =
        film.band_name(atmosphere_layer(AtmospherePart::surface, c, band_count));
    added.emplace_back(kReflectancePrefix + name.substr(std::string(kSurfacePrefix).size()),
                       std::move(r));
  }
  // Added after every plane is read: add_band may move the film's planes.
  for (auto& [name, r] : added) film.add_band(name, std::move(r));
}

}  // namespace landsim::renderer
