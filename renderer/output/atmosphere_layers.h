#pragma once
// The atmosphere's parts per pixel (docs/SENSOR.md "The atmosphere's parts per pixel"), with
// [render] atmosphere_layers: what the air adds between camera and surface (path radiance),
// the transmittance from the surface to the camera, the radiance leaving the surface toward
// the camera, the direct and diffuse irradiance on the surface, and the surface's own
// (bottom-of-atmosphere) reflectance factor; so that, pixel by pixel,
//   apparent radiance = path radiance + transmittance x surface radiance
// and the surface's reflectance factor is pi x surface radiance / (direct + diffuse).
// Each part in CIE X, Y, Z and in every band and channel of the scene, as film planes after the
// scene's bands.
#include <string>
#include <vector>

#include "renderer/output/film.h"
#include "renderer/spectra/spectrum.h"

namespace landsim::renderer {

struct SpectralBand;

enum class AtmospherePart : int { path = 0, transmittance, surface, direct, diffuse };
inline constexpr int kAtmosphereParts = 5;

// A sample's parts, spectral: radiances (as the path's), the camera segment's transmittance,
// and irradiances on the surface's side facing the camera. `through` is the surface's
// radiance as it arrives at the camera (transmittance x surface radiance): what the film
// accumulates in its surface planes until finish_atmosphere_layers.
struct AtmosphereSample {
  Spectrum path, transmittance, through, direct, diffuse;
};

// The planes' names, in film order: for each part, its X, Y, Z, then each band's layer
// ("atmosphere.path.X", "atmosphere.path.band.red", "atmosphere.direct.photons.nir", ...).
std::vector<std::string> atmosphere_layer_names(const std::vector<SpectralBand>& bands);
// The film plane of `part`'s channel `channel` (0-2: X, Y, Z; 3 on: the scene's bands), the
// scene having `band_count` bands.
int atmosphere_layer(AtmospherePart part, int channel, int band_count);

// A sample's parts as the film accumulates them: CIE X, Y, Z (radiances and irradiances by
// the colour-matching functions, Y in the image's units; the transmittance of an equal-energy
// spectrum in each channel; never R, G, B, whose ratios a saturated colour takes negative) and band
// integrals (the transmittance weighed by the band's response), written to `layers` from
// atmosphere_layer(part, 0, bands.size()).
void atmosphere_layer_values(const AtmosphereSample& s, const std::vector<SpectralBand>& bands,
                             float* layers);

// After the samples (the image set does it: a film from Renderer::render still holds the
// transmitted radiance in its surface planes): the surface planes divided by the
// transmittance, so that apparent = path + transmittance x surface holds in every pixel and
// layer exactly (0 where nothing is let through); and "atmosphere.reflectance.<layer>" added,
// pi x surface / (direct + diffuse), 0 where that irradiance is 0. `band_count`: the scene's
// bands (before the parts' planes).
void finish_atmosphere_layers(Film& film, int band_count);

}  // namespace landsim::renderer
