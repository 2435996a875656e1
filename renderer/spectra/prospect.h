#pragma once
// PROSPECT-D leaf optics (Feret, Gitelson, Noble and Jacquemoud 2017, "PROSPECT-D: Towards
// modeling leaf optical properties through a complete lifecycle", Remote Sensing of
// Environment 193): a leaf as N absorbing plates (Jacquemoud and Baret 1990), the first with
// a rough surface (Allen's transmissivity averaged over incidence up to 40 degrees), the
// remaining N - 1 combined by Stokes' equations. The absorption is the contents times their
// specific absorption coefficients (data/spectra/prospect_d_dataSpec_PDB.txt, compiled in).
#include <vector>

#include "renderer/spectra/spectrum.h"
#include "trees/leaf_contents.h"

namespace landsim::renderer {

using trees::LeafContents;

struct LeafSpectra {
  std::vector<double> wavelength, reflectance, transmittance;  // 1 nm, 400-2500 nm
};

// Directional-hemispherical reflectance and transmittance of the leaf at 1 nm from 400 nm
// to `last_nm` (at most 2500).
LeafSpectra prospect_d(const LeafContents& leaf, double last_nm = 2500.0);

// The same averaged over landsim's bins (the 380-400 nm part of the first bin holds the
// 400 nm value: the model's data start there).
struct LeafOptics {
  Spectrum reflectance, transmittance;
};
LeafOptics leaf_optics(const LeafContents& leaf);

}  // namespace landsim::renderer
