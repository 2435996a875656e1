#pragma once
// A sensor band's response file (docs/SCENARIO.md [[bands]]): CSV rows of wavelength (nm)
// and relative response, read with one clear message per mistake (file:line); and the layer a
// sensor channel renders into.
#include <string>
#include <string_view>
#include <vector>

#include "renderer/spectra/sensor_band.h"

namespace landsim::scenes {

// Parses `text` (the file `file`): rows "wavelength, response" separated by commas, tabs or
// spaces; '#' comments, blank lines and one header line are skipped. Wavelengths must not
// decrease, responses are >= 0 and not all zero, and the response must be zero outside
// 380-1020 nm (landsim's spectra). Throws InputError.
std::vector<renderer::ResponsePoint> parse_band_response(std::string_view text,
                                                         const std::string& file);

// The layer of sensor channel `name`: "photons.<name>" (the scene's band and the image's
// layer both take it).
std::string photon_layer(const std::string& name);

}  // namespace landsim::scenes
