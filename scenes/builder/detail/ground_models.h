#pragma once
// The ground's reflectance models in the scene (docs/GROUND.md "Reflectance models"): each
// material's from [[ground.brdf]], the plain's (the surroundings' when the scenario names
// them, else that of the material most of the grid's edge is, so the plain continues the
// ground as its albedo and spectrum do), and the energy check: a model whose
// directional-hemispherical reflectance at the material's own reflectance exceeds 1 at any
// incidence is refused, naming its table (for the materials the ground shows).
#include "renderer/scene.h"
#include "scenes/builder/detail/plain_albedo.h"
#include "scenes/scenario/scenario.h"

namespace landsim::scenes::detail {

// After the ground's materials and spectra are set. Throws InputError.
void set_ground_models(const Scenario& s, const EdgeGround& edge, renderer::Scene& scene);

}  // namespace landsim::scenes::detail
