#pragma once
// Named sets of sensor channels (docs/SENSOR.md "Channels"): spectral responses for users
// without their camera's curves. Not any camera's: a camera's own response files (one CSV
// per channel) are what a study of that camera should give.
#include <optional>
#include <string>
#include <vector>

#include "renderer/spectra/sensor_band.h"

namespace landsim::renderer {

struct PresetChannel {
  std::string name;
  std::vector<ResponsePoint> response;  // relative, peak 1
};

// "rgb": R, G, B from the CIE 1931 functions, x-bar without its short-wavelength lobe (below
// 505 nm), y-bar and z-bar: non-negative, so physically realisable, with a colour camera's
// overlaps. "xyz": X, Y, Z, the CIE 1931 functions themselves (a colorimeter). "luminance":
// Y alone (a photometer, a monochrome camera behind a photopic filter). Empty for other names.
std::optional<std::vector<PresetChannel>> channel_preset(const std::string& name);

// The names channel_preset knows, for messages.
const char* channel_preset_names();

}  // namespace landsim::renderer
