#pragma once
// What landsim's wavelength bins stand for in a run (docs/SPECTRAL.md "Monochromatic runs"):
// by default each bin is the mean over its 20 nm; in a monochromatic run (as radiative-transfer
// codes run, one wavelength at a time) the bin that holds the named wavelength stands for that
// wavelength alone. Only quantities that are functions of wavelength (the air's Rayleigh and
// ozone cross sections, an aerosol's optics, the sun's spectrum) are evaluated there; spectra
// landsim defines per bin (colours, soils, leaves) are piecewise constant over the bins, so
// their value at the wavelength is their bin's.
#include <algorithm>
#include <optional>

#include "renderer/spectra/spectrum.h"

namespace landsim::renderer {

// The bin that holds `nm` (a wavelength on a bin's edge belongs to the bin above it, the
// last edge to the last bin).
inline int bin_of(double nm) {
  return std::clamp(static_cast<int>((nm - kFirstWavelength) / kBinWidth), 0, kSpectrumBins - 1);
}

struct SpectralGrid {
  // A monochromatic run's wavelength (nm, within kFirstWavelength-kLastWavelength); empty: the
  // bins' means.
  std::optional<double> monochromatic_nm;

  bool monochromatic(int k) const { return monochromatic_nm && bin_of(*monochromatic_nm) == k; }
  // The wavelength bin k is evaluated at where one wavelength serves it (a wavelength law such
  // as Angstrom's): the bin's centre, or the monochromatic wavelength.
  double wavelength(int k) const { return monochromatic(k) ? *monochromatic_nm : bin_centre(k); }
  // Per bin the mean of f(wavelength in nm) over the bin at 1 nm midpoints; f at the
  // monochromatic wavelength in its bin.
  template <class F>
  Spectrum average(F&& f) const {
    Spectrum s;
    const int steps = static_cast<int>(kBinWidth);
    for (int k = 0; k < kSpectrumBins; ++k) {
      if (monochromatic(k)) {
        s[k] = static_cast<float>(f(*monochromatic_nm));
        continue;
      }
      double sum = 0.0;
      for (int i = 0; i < steps; ++i) sum += f(bin_start(k) + i + 0.5);
      s[k] = static_cast<float>(sum / steps);
    }
    return s;
  }
};

}  // namespace landsim::renderer
