#pragma once
// Applying what a caller chooses for one render beyond the scenario's keys (RenderChoices,
// scenario.h: samples, threads, image size, the one view). `landsim render`'s options and the
// Python module's `render` arguments go through the same function, so both render the same
// image; the scenario keeps them, so each randomised image gets them too.
#include <optional>
#include <string>

#include "scenes/scenario/scenario.h"

namespace landsim::scenes {

// Sizes win over the scenario's; a lone width or height keeps each view's aspect ratio.
// InputError for an explosive size.
void override_view_sizes(Scenario& s, std::optional<int> width, std::optional<int> height);

// Applies `c` to `s`: the chosen view alone stays (InputError naming the views there are).
void apply_render_choices(Scenario& s, const RenderChoices& c);

}  // namespace landsim::scenes
