#include "renderer/spectra/channel_presets.h"

#include <algorithm>
#include <functional>

#include "renderer/spectra/colour_matching.h"
#include "renderer/spectra/spectrum.h"

namespace landsim::renderer {
namespace {

// A response sampled every 5 nm over landsim's spectra, scaled to peak 1. The analytic fits'
// tails below 1e-3 of the peak are zero (under 0.1% of the response), as a real filter's
// would be; the path tracer's roulette ignores such tails of any response anyway
// (transport/path_tracer.cpp seen_bins).
std::vector<ResponsePoint> sampled(const std::function<double(double)>& f) {
  std::vector<ResponsePoint> points;
  double peak = 0.0;
  for (double nm = kFirstWavelength; nm <= kLastWavelength + 1e-9; nm += 5.0) {
    points.push_back({nm, std::max(0.0, f(nm))});
    peak = std::max(peak, points.back().response);
  }
  for (ResponsePoint& p : points) p.response = p.response < 1e-3 * peak ? 0.0 : p.response / peak;
  return points;
}

// The wavelength below which x-bar's blue lobe is dropped from the "rgb" preset's R: near the
// lobes' minimum between them (x-bar is below 0.5% of its peak there).
constexpr double kRedCut = 505.0;

}  // namespace

std::optional<std::vector<PresetChannel>> channel_preset(const std::string& name) {
  const auto x = [](double nm) { return cie1931_xyz_bar(nm).x; };
  const auto y = [](double nm) { return cie1931_xyz_bar(nm).y; };
  const auto z = [](double nm) { return cie1931_xyz_bar(nm).z; };
  if (name == "rgb")
    return std::vector<PresetChannel>{
        {"R", sampled([&](double nm) { return nm < kRedCut ? 0.0 : x(nm); })},
        {"G", sampled(y)},
        {"B", sampled(z)}};
  if (name == "xyz")
    return std::vector<PresetChannel>{{"X", sampled(x)}, {"Y", sampled(y)}, {"Z", sampled(z)}};
  if (name == "luminance") return std::vector<PresetChannel>{{"Y", sampled(y)}};
  return std::nullopt;
}

const char* channel_preset_names() { return "\"rgb\", \"xyz\" or \"luminance\""; }

}  // namespace landsim::renderer
