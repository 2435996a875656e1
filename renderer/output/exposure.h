#pragma once
// The preview PNG's exposure. Images are in photometric units (Y in cd/m2), so the preview
// needs a camera's exposure: an exposure value at ISO 100 (EV100) maps luminance L to the
// display's linear input L / (1.2 x 2^EV100), ISO 12232's saturation-based rule (a luminance
// of 1.2 x 2^EV100 just reaches white). Automatic exposure chooses EV100 so that the image's
// log-average luminance lands on the key value 0.18 (middle grey, Reinhard et al. 2002,
// "Photographic Tone Reproduction for Digital Images", section 3.1). docs/ATMOSPHERE.md.
#include <optional>

#include "renderer/output/film.h"

namespace landsim::renderer {

inline constexpr double kExposureKey = 0.18;

// The log-average (geometric mean) luminance of the film's pixels, cd/m2; a tiny floor keeps
// black pixels from driving it to zero.
double log_average_luminance(const Film& film);
// EV100 for `film`: the fixed value when given, else the automatic one.
double exposure_ev100(const Film& film, std::optional<double> fixed_ev100);
// The linear factor the preview applies for an EV100.
double preview_gain(double ev100);

}  // namespace landsim::renderer
