#pragma once
// Randomised image sets ([randomise], docs/SCENARIO.md "Randomised image sets"): what each
// image of the set draws, and its scenario: the file read again with the draws applied as
// `--set` overrides, so a drawn value passes the same checks as one written in the file.
#include <cstddef>
#include <string>
#include <vector>

#include "scenes/scenario/scenario.h"

namespace landsim::scenes {

// The images of the scenario's set: [randomise] images, else 1.
std::size_t randomised_images(const Scenario& s);

// What image `image` (0-based) draws, as "key=value" overrides in the order of the table's
// keys; each value from counters of ([render] seed, [randomise] seed, image, key), so adding
// a key leaves the others' draws as they were.
std::vector<std::string> randomised_sets(const Scenario& s, std::size_t image);

// The scenario of randomised image `image`: read again with its draws applied; `variation`
// is image + 1 and `variation_sets` its draws. InputError naming the image and the draw when
// a drawn value is refused. Without [randomise]: the scenario itself.
Scenario randomised_scenario(const Scenario& s, std::size_t image);

}  // namespace landsim::scenes
