#pragma once
// Illumination truth per pixel (docs/OUTPUTS.md "Illumination truth"), with [render]
// illumination_layers: whether the sun lights the surface a pixel sees (cast shadows and
// surfaces turned from the sun both read 0; leaves and grass, lit through, read 1 either
// side), and its sky-view factor, the share of a uniform sky's light it receives against open
// flat ground (1 there, 0.5 for a wall in the open, less in a valley or under a crown). Both
// are geometry alone (the air's transmittance left out), averaged over the pixel's samples
// that meet a surface: a shadow's edge reads between 0 and 1, a pixel of sky reads NaN.
#include <string>
#include <vector>

#include "renderer/output/film.h"

namespace landsim::renderer {

enum class IlluminationLayer : int { sunlit = 0, sky_view, surface };
inline constexpr int kIlluminationLayers = 3;

// The planes' names, in film order: "illumination.sunlit", "illumination.sky_view", and
// "illumination.surface" (the share of the pixel's samples that met a surface).
std::vector<std::string> illumination_layer_names();
// The film plane of `layer`: after the scene's `band_count` bands and, with
// `atmosphere_layers`, the atmosphere's parts (make_film's order).
int illumination_layer(IlluminationLayer layer, int band_count, bool atmosphere_layers);

// After the samples: sunlit and sky_view over the surface share (NaN where no sample met a
// surface). The film must hold the three planes.
void finish_illumination_layers(Film& film);

}  // namespace landsim::renderer
