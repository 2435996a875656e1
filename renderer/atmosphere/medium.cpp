#include "renderer/atmosphere/medium.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <utility>
#include <vector>

#include "renderer/atmosphere/aerosol_model.h"
#include "renderer/atmosphere/standard_atmosphere.h"
#include "renderer/spectra/spectral_colour.h"

namespace landsim::renderer {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
// Past this exponent an exponential density is taken as zero (e^-700 = 1e-304).
constexpr double kNegligibleExponent = 700.0;
// Below this vertical rate (per metre of path, in scale heights) a ray counts as level.
constexpr double kLevel = 1e-9;
// The air's density scale height (metres): the Rayleigh optical depth of the whole column over
// it is the sea-level scattering coefficient.
constexpr double kMolecularScaleHeight = 8000.0;
constexpr double kReferenceWavelength = 550.0;  // nm: where visibility is defined

PhaseFunction aerosol_phase(const Haze& h) {
  switch (h.phase) {
    case AerosolPhase::isotropic:
      return PhaseFunction::isotropic();
    case AerosolPhase::rayleigh:
      return PhaseFunction::rayleigh();
    case AerosolPhase::table:
      return PhaseFunction::table(h.phase_angles, h.phase_values);
    case AerosolPhase::legendre:
      return PhaseFunction::legendre(h.phase_moments);
    case AerosolPhase::henyey_greenstein:
      break;
  }
  return PhaseFunction::henyey_greenstein(h.asymmetry);
}

// The albedo as a spectrum: a grey exactly (the plane-parallel checks' 0.99 must be 0.99 in
// every bin), a colour upsampled.
Spectrum albedo_spectrum(const Vec3f& a) {
  if (a.x == a.y && a.y == a.z) return Spectrum::constant(std::clamp(a.x, 0.0f, 1.0f));
  Spectrum s = reflectance_spectrum(a);
  for (float& v : s.v) v = std::clamp(v, 0.0f, 1.0f);
  return s;
}

// Angstrom's law per bin, relative to 550 nm, at each bin's wavelength.
Spectrum angstrom_extinction(double angstrom, const SpectralGrid& grid) {
  Spectrum s;
  for (int k = 0; k < kSpectrumBins; ++k)
    s[k] = static_cast<float>(std::pow(grid.wavelength(k) / kReferenceWavelength, -angstrom));
  return s;
}

// Bin k's phase function of a model: at the monochromatic wavelength, or the mean over the
// bin's 1 nm steps weighted by what each scatters (the light a bin's scattering sends into a
// direction is the sum of its wavelengths').
PhaseFunction bin_phase_of(const AerosolModel& model, const SpectralGrid& grid, int k) {
  if (grid.monochromatic(k)) return model.phase(*grid.monochromatic_nm);
  std::vector<double> mean(model.angles_deg().size());
  for (int i = 0; i < static_cast<int>(kBinWidth); ++i) {
    const double nm = bin_start(k) + i + 0.5;
    const double w = model.relative_extinction(nm) * model.single_scattering_albedo(nm);
    const std::vector<double> p = model.phase_values(nm);
    for (std::size_t j = 0; j < mean.size(); ++j) mean[j] += w * p[j];
  }
  return PhaseFunction::table(model.angles_deg(), mean);  // normalised there
}

// A named model's optics: per bin its extinction (relative to 550 nm), scattering and phase
// function, means over the bin as for the air (docs/ATMOSPHERE.md "Aerosol models by
// wavelength": the continental model's asymmetry is 0.618 at 550 nm, 0.584 at 670 nm). The
// directions are drawn from the phase function at the monochromatic wavelength, or at 550 nm.
void set_model_optics(MediumComponent& aerosol, const AerosolModel& model,
                      const SpectralGrid& grid) {
  aerosol.extinction = grid.average([&](double nm) { return model.relative_extinction(nm); });
  aerosol.scattering = grid.average([&](double nm) {
    return model.relative_extinction(nm) * model.single_scattering_albedo(nm);
  });
  aerosol.phase = model.phase(grid.monochromatic_nm.value_or(kReferenceWavelength));
  auto bins = std::make_shared<std::array<PhaseFunction, kSpectrumBins>>();
  for (int k = 0; k < kSpectrumBins; ++k)
    (*bins)[static_cast<std::size_t>(k)] = bin_phase_of(model, grid, k);
  aerosol.bin_phase = std::move(bins);
}

// An exponential profile along a ray, its density `at_origin` at the ray's origin and its
// exponent falling by `rate` a metre of the ray: the unit depth over [0, t] and the density at
// t, both from one expm1 (t may be infinite).
std::pair<double, double> exponential_along(double at_origin, double rate, double t) {
  if (std::abs(rate) < kLevel) return {std::isinf(t) ? kInfinity : at_origin * t, at_origin};
  if (std::isinf(t))
    return rate > 0.0 ? std::pair{at_origin / rate, 0.0} : std::pair{kInfinity, kInfinity};
  const double e = std::expm1(-rate * t);
  return {-at_origin * e / rate, at_origin * (1.0 + e)};
}

// A component along one ray, its density at the origin found once: the unit depth over
// [0, s] and the density at s (Newton's method in Medium::distance_at asks for both at every
// step: with three transcendentals a step it took 3.4% of a default render's time).
class AlongRay {
 public:
  AlongRay(const MediumComponent& c, const Vec3& o, const Vec3& d)
      : c_(c), o_(o), d_(d), at_origin_(c.density(o.z)), rate_(d.z / c.scale_height) {}
  std::pair<double, double> at(double s) const {
    if (!c_.present) return {0.0, 0.0};
    if (c_.slab || c_.profile) return {c_.unit_depth(o_, d_, s), c_.density(o_.z + s * d_.z)};
    return exponential_along(at_origin_, rate_, s);
  }

 private:
  const MediumComponent& c_;
  Vec3 o_, d_;
  double at_origin_, rate_;
};

}  // namespace

double rayleigh_scattering(double nm) {
  // Bodhaine, Wood, Dutton and Slusser 1999, "On Rayleigh optical depth calculations",
  // J. Atmos. Oceanic Technol. 16, equation (30): the column's optical depth at sea level
  // (1013.25 hPa), lambda in micrometres; over the density scale height.
  const double l = nm * 1e-3, l2 = l * l;
  const double tau = 0.0021520 * (1.0455996 - 341.29061 / l2 - 0.90230850 * l2) /
                     (1.0 + 0.0027059889 / l2 - 85.968563 * l2);
  return tau / kMolecularScaleHeight;
}

double MediumComponent::density(double z) const {
  if (!present) return 0.0;
  if (profile) return profile->density(z - z0);
  if (slab) return z >= z0 && z <= z1 ? density0 : 0.0;
  // Past e^-700 (1e-304) the density is nothing any sum can see; exp's underflow there goes
  // through glibc's slow error path (3% of a render, measured by perf).
  const double x = (z - z0) / scale_height;
  return x > kNegligibleExponent ? 0.0 : density0 * std::exp(-x);
}

double MediumComponent::unit_depth(const Vec3& o, const Vec3& d, double t) const {
  if (!present || t <= 0.0) return 0.0;
  if (profile) return profile->along(o.z - z0, d.z, t);
  if (slab) {
    double in = 0.0, out = t;
    if (std::abs(d.z) < 1e-12) {
      if (o.z < z0 || o.z > z1) return 0.0;
    } else {
      const double a = (z0 - o.z) / d.z, b = (z1 - o.z) / d.z;
      in = std::max(in, std::min(a, b));
      out = std::min(out, std::max(a, b));
    }
    return out > in ? density0 * (out - in) : 0.0;
  }
  return exponential_along(density(o.z), d.z / scale_height, t).first;
}

double MediumComponent::distance_at(const Vec3& o, const Vec3& d, double t, double depth) const {
  if (!present || depth <= 0.0) return 0.0;
  if (profile) return profile->length_at(o.z - z0, d.z, t, depth);
  if (slab) {
    double in = 0.0, out = t;
    if (std::abs(d.z) >= 1e-12) {
      const double a = (z0 - o.z) / d.z, b = (z1 - o.z) / d.z;
      in = std::max(in, std::min(a, b));
      out = std::min(out, std::max(a, b));
    } else if (o.z < z0 || o.z > z1) {
      return t;
    }
    const double s = in + depth / density0;
    return s < out ? s : t;
  }
  const double at_origin = density(o.z);
  const double k = d.z / scale_height;
  double s;
  if (std::abs(k) < kLevel) {
    s = depth / at_origin;
  } else {
    const double arg = 1.0 - depth * k / at_origin;  // the density left, as a share
    s = arg > 0.0 ? -std::log(arg) / k : kInfinity;
  }
  return std::isfinite(s) ? std::min(s, t) : t;
}

Medium::Medium(const Haze& h, const SpectralGrid& grid) {
  if (!h.enabled) return;
  if (h.column) {
    build_atmosphere(h, grid);
    return;
  }
  MediumComponent& aerosol = components_[0];
  MediumComponent& air = components_[1];
  aerosol.phase = aerosol_phase(h);
  const Spectrum albedo = albedo_spectrum(h.albedo);
  if (h.layer) {
    // The plane-parallel layer: homogeneous, grey, between the base and the top.
    if (!(h.layer->top > 0.0) || !(h.layer->optical_depth > 0.0)) return;
    aerosol.present = aerosol.slab = true;
    aerosol.z0 = h.base_height;
    aerosol.z1 = h.base_height + h.layer->top;
    aerosol.density0 = h.layer->optical_depth / h.layer->top;
    aerosol.extinction = Spectrum::constant(1.0f);
    aerosol.scattering = albedo;
    enabled_ = true;
    return;
  }
  if (!(h.visibility > 0.0)) return;
  const double air_at_base = h.molecular ? rayleigh_scattering(kReferenceWavelength) *
                                               std::exp(-h.base_altitude / kMolecularScaleHeight)
                                         : 0.0;
  if (h.molecular) {
    air.present = true;
    air.reaches_sky = false;
    air.z0 = h.base_height;
    air.scale_height = kMolecularScaleHeight;
    air.density0 = air_at_base;
    air.phase = PhaseFunction::rayleigh();
    for (int k = 0; k < kSpectrumBins; ++k)
      air.extinction[k] = static_cast<float>(rayleigh_scattering(grid.wavelength(k)) /
                                             rayleigh_scattering(kReferenceWavelength));
    air.scattering = air.extinction;  // molecules absorb nothing here
  }
  // Koschmieder's visibility holds for the whole extinction at 550 nm; the aerosol takes what
  // the air leaves (none past the air's own visibility, 330 km at sea level).
  aerosol.density0 = std::max(0.0, visibility_extinction(h) - air_at_base);
  aerosol.present = aerosol.density0 > 0.0;
  aerosol.z0 = h.base_height;
  aerosol.scale_height = h.scale_height;
  aerosol.extinction = angstrom_extinction(h.angstrom, grid);
  aerosol.scattering = aerosol.extinction * albedo;
  enabled_ = aerosol.present || air.present;
}

void Medium::build_atmosphere(const Haze& h, const SpectralGrid& grid) {
  // The heights: the base (the lowest ground) stands at its altitude above sea level; the
  // tables are by altitude, so a component's z0 is the scene's sea level.
  const double sea_level = h.base_height - h.base_altitude;
  const MolecularColumn& column = *h.column;
  const StandardAtmosphere& standard = us_standard_atmosphere();
  MediumComponent& aerosol = components_[0];
  MediumComponent& air = components_[1];
  MediumComponent& ozone = components_[2];
  if (column.scattering) {
    // Rayleigh: the density is the molecules' number times the cross section at 550 nm.
    const double sigma550 = rayleigh_cross_section(kReferenceWavelength);
    auto profile = std::make_shared<DensityProfile>(standard.air);
    profile->scale(sigma550);
    air.present = true;
    air.profile = std::move(profile);
    air.z0 = sea_level;
    air.phase = PhaseFunction::rayleigh();
    air.extinction = rayleigh_cross_sections(grid) * static_cast<float>(1.0 / sigma550);
    air.scattering = air.extinction;  // the molecules' absorption is ozone's, below
  }
  if (column.absorption) {
    // Ozone absorbs only; its profile's shape is the standard's, its column the key's.
    const double sigma550 = ozone_cross_section(kReferenceWavelength);
    auto profile = std::make_shared<DensityProfile>(standard.ozone);
    const double own = profile->column_above(-1e9);
    const double wanted = column.ozone_column > 0.0 ? column.ozone_column * kDobsonUnit : own;
    profile->scale(sigma550 * wanted / own);
    ozone.present = true;
    ozone.profile = std::move(profile);
    ozone.z0 = sea_level;
    ozone.extinction = ozone_cross_sections(grid) * static_cast<float>(1.0 / sigma550);
    ozone.scattering = Spectrum{};
  }
  if (h.aerosol) {
    aerosol.z0 = h.base_height;
    if (!h.aerosol_model.empty()) {
      set_model_optics(aerosol, *AerosolModel::named(h.aerosol_model), grid);
    } else {
      aerosol.phase = aerosol_phase(h);
      aerosol.extinction = angstrom_extinction(h.angstrom, grid);
      aerosol.scattering = aerosol.extinction * albedo_spectrum(h.albedo);
    }
    const bool uniform = h.aerosol_profile == AerosolProfile::uniform;
    const double thickness = h.uniform_top - h.uniform_bottom;
    if (uniform) {
      aerosol.slab = true;
      aerosol.z0 = h.base_height + h.uniform_bottom;
      aerosol.z1 = h.base_height + h.uniform_top;
    } else {
      aerosol.scale_height = h.scale_height;
    }
    if (h.aerosol_optical_depth) {
      aerosol.density0 = *h.aerosol_optical_depth / (uniform ? thickness : h.scale_height);
    } else {
      // Koschmieder's visibility holds for the whole extinction at the base at 550 nm: the
      // aerosol takes what the air and ozone there leave.
      double others = 0.0;
      for (const MediumComponent* m : {&air, &ozone})
        if (m->present) others += m->density(h.base_height);
      aerosol.density0 = std::max(0.0, visibility_extinction(h) - others);
    }
    aerosol.present = aerosol.density0 > 0.0;
  }
  enabled_ = aerosol.present || air.present || ozone.present;
}

Spectrum MediumComponent::phase_values(float cos_theta) const {
  if (!bin_phase) return Spectrum::constant(phase.eval(cos_theta));
  Spectrum out;
  for (int k = 0; k < kSpectrumBins; ++k)
    out[k] = (*bin_phase)[static_cast<std::size_t>(k)].eval(cos_theta);
  return out;
}

double Medium::top() const {
  double top = -kInfiniteDistance;
  for (const MediumComponent& m : components_) {
    if (!m.present) continue;
    // A table's last node is 119.5 km: its top layer's upper edge.
    const double t = m.profile ? m.z0 + m.profile->top() + 500.0
                     : m.slab  ? m.z1
                               : m.z0 + 40.0 * m.scale_height;
    top = std::max(top, t);
  }
  return top;
}

UnitDepths Medium::unit_depths(const Vec3& o, const Vec3& d, double t, bool ends_on_surface) const {
  UnitDepths out{};
  for (int c = 0; c < kMediumComponents; ++c)
    if (acts(c, ends_on_surface))
      out[static_cast<std::size_t>(c)] = component(c).unit_depth(o, d, t);
  return out;
}

double Medium::optical_depth(const UnitDepths& depths, int k) const {
  double tau = 0.0;
  for (int c = 0; c < kMediumComponents; ++c)
    if (depths[static_cast<std::size_t>(c)] > 0.0)
      tau += depths[static_cast<std::size_t>(c)] * component(c).extinction[k];
  return tau;
}

Spectrum Medium::transmittance(const UnitDepths& depths, const BinSet& bins) const {
  // Float exponentials: a quarter of a hazy render's time was spent in double ones.
  const auto d0 = static_cast<float>(depths[0]), d1 = static_cast<float>(depths[1]),
             d2 = static_cast<float>(depths[2]);
  const Spectrum& e0 = components_[0].extinction;
  const Spectrum& e1 = components_[1].extinction;
  const Spectrum& e2 = components_[2].extinction;
  Spectrum t;
  for (int i = 0; i < bins.count; ++i) {
    const int k = bins.index[static_cast<std::size_t>(i)];
    // Ozone's depth only where it is present: the sum of the other two stays as it was.
    const float tau = d0 * e0[k] + d1 * e1[k];
    const float all = d2 > 0.0f ? tau + d2 * e2[k] : tau;
    // Past e^-87 (float's least normal) nothing passes that any sum can see; expf's underflow
    // there takes glibc's slow error path.
    t[k] = all > 87.0f ? 0.0f : std::exp(-all);
  }
  return t;
}

std::pair<UnitDepths, UnitDepths> Medium::depths_and_densities(const Vec3& o, const Vec3& d,
                                                               double s,
                                                               bool ends_on_surface) const {
  std::pair<UnitDepths, UnitDepths> out{};
  for (int c = 0; c < kMediumComponents; ++c) {
    if (!acts(c, ends_on_surface)) continue;
    const auto [depth, density] = AlongRay(component(c), o, d).at(s);
    out.first[static_cast<std::size_t>(c)] = depth;
    out.second[static_cast<std::size_t>(c)] = density;
  }
  return out;
}

Spectrum Medium::transmittance(const UnitDepths& depths) const {
  return transmittance(depths, BinSet::all());
}

double Medium::extinction(double z, int k, bool ends_on_surface) const {
  double sigma = 0.0;
  for (int c = 0; c < kMediumComponents; ++c)
    if (acts(c, ends_on_surface)) sigma += component(c).density(z) * component(c).extinction[k];
  return sigma;
}

double Medium::distance_at(const Vec3& o, const Vec3& d, double t, bool ends_on_surface, int k,
                           double tau) const {
  int acting = 0, only = 0;
  for (int c = 0; c < kMediumComponents; ++c)
    if (acts(c, ends_on_surface) && component(c).extinction[k] > 0.0f) {
      ++acting;
      only = c;
    }
  if (acting == 0) return t;
  if (acting == 1) return component(only).distance_at(o, d, t, tau / component(only).extinction[k]);
  // Two or more components (t finite, or a ray into the sky through the whole atmosphere):
  // Newton's method, kept inside a shrinking bracket. The optical depth is increasing and
  // concave or convex piecewise, so it converges in a few steps from the first acting
  // component's own answer. Each step needs the depth and its slope (the extinction there).
  std::array<std::optional<AlongRay>, kMediumComponents> along;
  std::array<double, kMediumComponents> e{};
  int first = -1;
  for (int c = 0; c < kMediumComponents; ++c)
    if (acts(c, ends_on_surface) && component(c).extinction[k] > 0.0f) {
      along[static_cast<std::size_t>(c)].emplace(component(c), o, d);
      e[static_cast<std::size_t>(c)] = component(c).extinction[k];
      if (first < 0) first = c;
    }
  double slope = 0.0;
  const auto excess = [&](double s) {  // the depth at s past tau; its slope in `slope`
    double depth = 0.0;
    slope = 0.0;
    for (std::size_t c = 0; c < along.size(); ++c) {
      if (!along[c]) continue;
      const auto [u, rho] = along[c]->at(s);
      depth += u * e[c];
      slope += rho * e[c];
    }
    return depth - tau;
  };
  double lo = 0.0, hi = t;
  if (!std::isfinite(hi)) hi = 1e9;
  if (excess(hi) <= 0.0) return t;
  double s = std::clamp(
      component(first).distance_at(o, d, hi, tau / e[static_cast<std::size_t>(first)]), lo, hi);
  for (int i = 0; i < 60; ++i) {
    const double f = excess(s);
    if (std::abs(f) <= 1e-9 * std::max(tau, 1e-12)) break;
    if (f > 0.0)
      hi = s;
    else
      lo = s;
    double next = slope > 0.0 ? s - f / slope : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (hi - lo <= 1e-9 * std::max(1.0, hi)) break;
    s = next;
  }
  return s;
}

}  // namespace landsim::renderer
