#pragma once
// The air as a participating medium (docs/ATMOSPHERE.md "The medium", "One atmosphere"): up
// to three components (aerosol, the air's molecules, ozone), each a density profile along z
// (exponential, a homogeneous slab, or tabulated: a standard atmosphere's) times a spectral
// extinction per unit density, a single-scattering albedo per bin and a phase function.
//
// [atmosphere] (Haze::column): the whole atmosphere from the ground to 120 km, the AFGL U.S.
// Standard profile's air (Rayleigh) and ozone (absorption) and the aerosol layer, every
// component acting on every segment: the sky is what this medium scatters.
// [haze] under the Hosek-Wilkie sky: aerosol (exponential, extinction from the visibility,
// Angstrom's wavelength law, OPAC's albedo and asymmetry) and the air's molecules (Rayleigh,
// 8 km scale height), the molecular component only on segments that end on a surface: the
// Hosek-Wilkie sky and sun already hold the clear atmosphere's Rayleigh scattering, so a
// segment that leaves into the sky must not take it again. The plane-parallel checks: one
// homogeneous layer.
//
// Optical depths have closed forms along any ray; a component's "unit depth" is the integral
// of its density profile, and a bin's optical depth is the sum over components of the unit
// depth times the component's extinction in that bin.
#include <array>
#include <cstdint>
#include <limits>
#include <memory>
#include <utility>

#include "core/vec3.h"
#include "renderer/atmosphere/density_profile.h"
#include "renderer/atmosphere/phase_function.h"
#include "renderer/scene.h"
#include "renderer/spectra/spectral_grid.h"
#include "renderer/spectra/spectrum.h"

namespace landsim::renderer {

inline constexpr int kMediumComponents = 3;  // aerosol, air, ozone (by index)
inline constexpr double kInfiniteDistance = std::numeric_limits<double>::infinity();

// Koschmieder's law: the whole extinction at 550 nm, per metre, at the haze's base (0 without
// haze). The medium's aerosol and air share it; the comparable tracer's uniform fog is it.
inline double visibility_extinction(const Haze& h) {
  return h.enabled && h.visibility > 0.0 ? 3.912 / h.visibility : 0.0;
}

// Wavelength bins by index: those an output sees (renderer/transport/path_tracer.cpp), where
// the medium's per-bin work is done; the others are left at zero (nothing reads them).
struct BinSet {
  std::array<std::uint8_t, kSpectrumBins> index{};
  int count = 0;
  static BinSet all() {
    BinSet b;
    for (int k = 0; k < kSpectrumBins; ++k)
      b.index[static_cast<std::size_t>(b.count++)] = static_cast<std::uint8_t>(k);
    return b;
  }
};
using UnitDepths = std::array<double, kMediumComponents>;

struct MediumComponent {
  bool present = false;
  bool slab = false;          // homogeneous between z0 and z1; else exponential from z0 upward
  double density0 = 0.0;      // per metre, at z0 (the profile times the extinction at 550 nm)
  double z0 = 0.0, z1 = 0.0;  // the base; the slab's top
  // Tabulated instead: the density at scene height z is profile(z - z0), z0 sea level, already
  // in extinction at 550 nm per metre.
  std::shared_ptr<const DensityProfile> profile;
  double scale_height = 1.0;
  bool reaches_sky = true;  // false: only on segments that end on a surface
  Spectrum extinction;      // per unit density (1 at 550 nm for the aerosol)
  Spectrum scattering;      // extinction x single-scattering albedo
  // Every bin's phase function; where `bin_phase` is set, the one directions are drawn from.
  PhaseFunction phase;
  // Each bin's own (an aerosol dataset by wavelength, docs/ATMOSPHERE.md "Aerosol models by
  // wavelength"); empty: `phase` in every bin.
  std::shared_ptr<const std::array<PhaseFunction, kSpectrumBins>> bin_phase;

  // The phase function's value per bin at the scattering angle's cosine.
  Spectrum phase_values(float cos_theta) const;

  double density(double z) const;
  // Integral of the density along o + s d for s in [0, t] (t may be infinite).
  double unit_depth(const Vec3& o, const Vec3& d, double t) const;
  // The distance s in [0, t] at which unit_depth reaches `depth` (t when it never does).
  double distance_at(const Vec3& o, const Vec3& d, double t, double depth) const;
};

class Medium {
 public:
  // Each bin's optics as `grid` says (its mean, or a monochromatic run's wavelength).
  explicit Medium(const Haze& haze, const SpectralGrid& grid = {});

  bool enabled() const { return enabled_; }
  const MediumComponent& component(int c) const { return components_[static_cast<std::size_t>(c)]; }
  // Whether component c acts on a segment that ends on a surface (false: leaves to the sky).
  bool acts(int c, bool ends_on_surface) const {
    const MediumComponent& m = component(c);
    return m.present && (ends_on_surface || m.reaches_sky);
  }

  UnitDepths unit_depths(const Vec3& o, const Vec3& d, double t, bool ends_on_surface) const;
  // Per bin exp(-sum_c depths[c] x extinction_c); in `bins` only (zero elsewhere).
  Spectrum transmittance(const UnitDepths& depths) const;
  Spectrum transmittance(const UnitDepths& depths, const BinSet& bins) const;
  Spectrum transmittance(const Vec3& o, const Vec3& d, double t, bool ends_on_surface) const {
    return transmittance(unit_depths(o, d, t, ends_on_surface));
  }
  Spectrum transmittance(const Vec3& o, const Vec3& d, double t, bool ends_on_surface,
                         const BinSet& bins) const {
    return transmittance(unit_depths(o, d, t, ends_on_surface), bins);
  }
  // unit_depths over [0, s] and each component's unit density at o + s d (0 where it does
  // not act) together: an exponential component's both from one expm1.
  std::pair<UnitDepths, UnitDepths> depths_and_densities(const Vec3& o, const Vec3& d, double s,
                                                         bool ends_on_surface) const;
  // Optical depth of bin k.
  double optical_depth(const UnitDepths& depths, int k) const;
  // Extinction of bin k at height z, per metre.
  double extinction(double z, int k, bool ends_on_surface) const;
  // The distance in [0, t] at which bin k's optical depth reaches `tau` (Newton's method on
  // the closed forms when two components act; exact with one).
  double distance_at(const Vec3& o, const Vec3& d, double t, bool ends_on_surface, int k,
                     double tau) const;
  // The height above which the medium holds nothing that counts: a slab's top, or forty
  // scale heights above an exponential component's base (its density down by e^-40 there).
  // What a sensor or sun infinitely far away starts its rays at. -infinity when disabled.
  double top() const;
  // Extinction at 550 nm for the aerosol alone, at the base (the visibility's).
  double aerosol_extinction_at_base() const { return components_[0].density0; }
  // The column's vertical optical depth of component c from height z to the top, at 550 nm.
  double vertical_depth(int c, double z) const {
    return component(c).unit_depth({0.0, 0.0, z}, {0.0, 0.0, 1.0}, kInfiniteDistance);
  }

 private:
  void build_atmosphere(const Haze& haze,
                        const SpectralGrid& grid);  // [atmosphere]: every component by its profile

  bool enabled_ = false;
  std::array<MediumComponent, kMediumComponents> components_;
};

// The air's Rayleigh scattering coefficient at sea level, per metre, at wavelength `nm`.
double rayleigh_scattering(double nm);

}  // namespace landsim::renderer
