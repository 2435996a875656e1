#pragma once
// A leaf's structure and contents in the units of the PROSPECT leaf model (Feret et al. 2017,
// PROSPECT-D), from which the renderer computes its reflectance and transmittance spectra
// (renderer/spectra/prospect.h, docs/SPECTRAL.md). The defaults are the typical green leaf of the
// PROSAIL literature.
namespace landsim::trees {

struct LeafContents {
  double structure = 1.5;     // N, the number of plates (1-3.5)
  double chlorophyll = 40.0;  // Cab, ug/cm2
  double carotenoids = 8.0;   // Car, ug/cm2
  double anthocyanins = 0.0;  // Ant, ug/cm2
  double brown = 0.0;         // Cbrown, arbitrary units (0 green, about 1 senescent)
  double water = 0.01;        // Cw, equivalent water thickness, cm
  double dry_matter = 0.009;  // Cm, g/cm2
  friend bool operator==(const LeafContents&, const LeafContents&) = default;
};

}  // namespace landsim::trees
