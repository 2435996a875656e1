#pragma once
// Where the light goes in a periodic cell (docs/CANOPIES.md "Measures"): light traced forward
// from the sun (or an isotropic sky), entering uniformly over the top of the cell or of its
// haze, followed through every scattering, on surfaces and in the haze, until it leaves
// upwards or is absorbed. The shares of that light reflected out of the top (the albedo:
// directional-hemispherical under the sun, bi-hemispherical under the sky), absorbed by
// leaves (fAPAR where the optics are those of the PAR), by trunks and stems, by the soil, by
// scene objects and by the haze, and reaching the soil directly or after scattering; each with
// its standard error. Reflected + absorbed = 1: nothing leaves a periodic cell sideways.
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
  DistantValue absorbed_haze;    // the medium over and in the cell
  DistantValue soil_direct;      // reaching the soil before any scattering
  DistantValue soil_diffuse;     // reaching it after scattering
  DistantValue lost;             // paths cut by the safety limit of legs or bounces
  // Reflected + absorbed + lost, path by path: 1 on average (Russian roulette, unbiased,
  // conserves light only on average), its standard error what closure is checked against.
  DistantValue total;
};

// Where the light comes from: the sun's beam (the reflected share is the directional-
// hemispherical reflectance, "black-sky albedo"), or the same radiance from every direction of
// the sky (bi-hemispherical reflectance, "white-sky albedo"; RAMI's BHR under isotropic light).
enum class Illumination { sun, isotropic };

struct EnergyOptions {
  std::uint64_t samples = 100000;  // paths from the light
  Illumination illumination = Illumination::sun;
  std::uint64_t seed = 1;
  int threads = 0;
};

// The shares of the light's luminance (every wavelength's share where the optics are grey),
// weighted by the sun's spectrum (by an equal-energy spectrum when the sun is dark).
// Throws std::invalid_argument without a periodic cell or with the sun down.
EnergyBudget measure_energy(const Scene& scene, const EnergyOptions& options);

}  // namespace landsim::renderer
