#pragma once
// Where the sun's light goes in a periodic cell (docs/CANOPIES.md "Measures"): light traced
// forward from the sun, entering uniformly over the cell's top, followed through every
// scattering until it leaves upwards or is absorbed. The shares of the sun's light reflected
// out of the cell (its directional-hemispherical reflectance, RAMI's albedo under the sun),
// absorbed by leaves (fAPAR where the optics are those of the PAR), by trunks and stems, by the
// soil, and reaching the soil directly or after scattering; each with its standard error.
// Reflected + absorbed = 1: nothing leaves a periodic cell sideways.
#include <cstdint>
#include <optional>

#include "renderer/measures/distant_measure.h"
#include "renderer/scene.h"

namespace landsim::renderer {

struct EnergyBudget {
  DistantValue reflected;        // leaving the cell's top
  DistantValue absorbed_leaves;  // leaves and grass
  DistantValue absorbed_stems;   // trunks, branches (bark)
  DistantValue absorbed_soil;    // the ground
  DistantValue absorbed_other;   // scene objects
  DistantValue soil_direct;      // reaching the soil before any scattering
  DistantValue soil_diffuse;     // reaching it after scattering
  DistantValue lost;             // paths cut by the safety limit of legs or bounces
};

struct EnergyOptions {
  std::uint64_t samples = 100000;  // paths from the sun
  std::uint64_t seed = 1;
  int threads = 0;
};

// The shares of the sun's luminance (every wavelength's share where the optics are grey).
// Throws std::invalid_argument without a periodic cell or with the sun down.
EnergyBudget measure_energy(const Scene& scene, const EnergyOptions& options);

}  // namespace landsim::renderer
