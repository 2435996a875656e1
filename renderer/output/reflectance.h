#pragma once
// Reflectance factors (docs/SENSOR.md "Irradiance and reflectance"): an image's downwelling
// irradiance E (renderer/atmosphere/downwelling.h) at the height of what its centre pixel
// sees, in RGB and in each of the scene's bands and channels; and layers pi L / E, the
// reflectance factor a remote-sensing user computes indices such as NDVI from. Haze path
// radiance stays in L, as a sensor sees it.
#include <vector>

#include "core/vec3.h"
#include "renderer/output/film.h"
#include "renderer/scene.h"

namespace landsim::renderer {

struct ImageIrradiance {
  double height = 0.0;                 // scene frame z it is taken at
  Vec3f rgb, direct_rgb, diffuse_rgb;  // lux-scaled Rec. 709 (Y: illuminance, lux)
  Vec3f xyz;                           // CIE 1931, lux-scaled (Y: illuminance)
  // Per scene band in order: W m-2 for radiance bands, photons s-1 m-2 for channels.
  std::vector<double> layers;
};

// At the height of the centre pixel's first hit (P.Z), or the haze's base where it sees sky.
ImageIrradiance image_irradiance(const Scene& scene, const Film& film);

// Adds "reflectance.X", ".Y", ".Z" (the CIE tristimulus reflectance factors: the pixel's X, Y,
// Z from its R, G, B, over E's) and "reflectance.<layer>" for every band layer the film holds
// (those of `e.layers`): pi x L / E; 0 where E is 0. Never negative: spectral integrals of
// non-negative light with non-negative weights (X, Y, Z rather than R, G, B, which a saturated
// colour takes below zero), float rounding of the R, G, B -> X, Y, Z matrix held at 0.
void add_reflectance(Film& film, const ImageIrradiance& e);

}  // namespace landsim::renderer
