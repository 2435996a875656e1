#pragma once
// The spectra of leaves, grass and soil (docs/SPECTRAL.md "Materials"):
// - leaves with PROSPECT contents: PROSPECT-D's reflectance and transmittance;
// - leaves and grass given only a colour: the colour upsampled in the visible, joined across
//   the red edge (700-750 nm) to the typical green leaf's near-infrared plateau, which no
//   pigment changes (chlorophyll and the others absorb nothing past 750 nm);
// - soil: the colour (dry soil's) upsampled in the visible, continued past 700 nm along the
//   measured dry soil spectrum's shape, and darkened by moisture as the measured wet soil is.
#include "core/vec3.h"
#include "renderer/scene.h"
#include "trees/leaf_contents.h"

namespace landsim::renderer {

SpectralOptics leaf_spectral_optics(const trees::LeafContents& leaf);
SpectralOptics coloured_leaf_optics(const Vec3f& reflectance, const Vec3f& transmittance);
// `moisture` 0 (the colour as given: dry) to 1 (as wet as the measured wet soil).
SpectralOptics soil_optics(const Vec3f& dry_colour, double moisture);

// The measured soil reflectance (data/spectra/prosail_soil_reflectance.txt), bin averages.
const Spectrum& dry_soil_reflectance();
const Spectrum& wet_soil_reflectance();

}  // namespace landsim::renderer
