#pragma once
// Radiance arriving from a direction that leaves the scene (the sun disc excluded: the sun
// is reached by next-event estimation only), with an importance-sampling table over the
// sphere for next-event estimation of the sky.
#include <array>
#include <memory>
#include <vector>

#include "core/vec3.h"
#include "renderer/atmosphere/direction_table.h"
#include "renderer/scene.h"
#include "renderer/spectra/spectrum.h"

namespace landsim::renderer {

class PreethamSky;
class HosekWilkieSky;

class SkyModel {
 public:
  // `grid`: what the bins of the atmosphere's sun spectrum stand for (a monochromatic run's
  // wavelength, or their means).
  SkyModel(const Sky& sky, const Sun& sun, Vec3f ground_albedo, const SpectralGrid& grid);
  ~SkyModel();
  SkyModel(SkyModel&&) noexcept;

  // The sun disc's radiance in `direction` (zero outside the disc): what a camera or mirror
  // ray that meets the sun sees. Its integral over the disc is the sun's irradiance, so it
  // agrees with next-event estimation; limb-darkened (Hosek and Wilkie 2013) under the
  // Hosek-Wilkie sky, uniform under the others.
  Vec3f sun_radiance(const Vec3f& direction) const;

  // Sky radiance above the horizon. Below it, where a ray leaves a finite terrain, the
  // radiance of an endless sunlit plain of `ground_albedo` (the scene's: the mean along the
  // grid's edge), unshadowed and infinitely far: what the comparable tracer and a scene
  // without ground see there. The path tracer meets the plain as a surface instead
  // (renderer/transport/plain.h).
  Vec3f radiance(const Vec3f& direction) const;
  // The horizon band's radiance at the azimuth of `direction`: the mean over elevations 0 to
  // 2 degrees. What haze converges to at long range (docs/ATMOSPHERE.md): a band, because
  // the Hosek-Wilkie fit's last half degree loses a third of its blue, which a haze layer's
  // own multiple scattering would not.
  Vec3f horizon_band_radiance(const Vec3f& direction) const;

  // Irradiance the sky alone gives a horizontal surface.
  Vec3f horizontal_irradiance() const { return sky_irradiance_; }
  // Radiance averaged over the whole sphere (sky above, the sunlit plain below): what haze
  // scatters toward the viewer from skylight, taken as isotropic.
  Vec3f mean_radiance() const { return mean_radiance_; }
  // What sample() draws from: the sky's luminance, cell by cell.
  const DirectionTable& table() const { return table_; }

  // Spectral counterparts (W m^-2 sr^-1 nm^-1 per bin; docs/SPECTRAL.md): Hosek-Wilkie's
  // spectral tables (the sun's and the sky's, continued past 720 nm by
  // renderer/spectra/near_infrared), scaled so that the sun's spectrum has the scene's sun
  // irradiance as its colour; the other models' RGB made spectra (emission_spectrum).
  Spectrum spectral_radiance(const Vec3f& direction) const;
  Spectrum sun_spectral_radiance(const Vec3f& direction) const;
  // On a surface facing the sun, W m^-2 nm^-1.
  const Spectrum& sun_spectral_irradiance() const { return sun_spectrum_; }
  Spectrum horizon_band_spectral(const Vec3f& direction) const;

  // A direction above the horizon drawn in proportion to luminance x solid angle; `pdf` per
  // steradian (zero below the horizon).
  Vec3f sample(float u1, float u2, float& pdf) const;
  float pdf(const Vec3f& direction) const;

 private:
  Vec3f above_horizon(const Vec3f& direction) const;
  Spectrum above_horizon_spectral(const Vec3f& direction) const;
  void build_spectra(const Sun& sun, double elevation, Vec3f ground_albedo,
                     const SpectralGrid& grid);

  void build_sun_disc(const Sun& sun, double elevation);  // elevation in radians

  Sky sky_;
  bool atmosphere_ = false;  // SkyKind::atmosphere: the sun at the top of the atmosphere
  std::unique_ptr<PreethamSky> preetham_;
  std::unique_ptr<HosekWilkieSky> hosek_wilkie_;
  Vec3f sun_direction_;
  float sun_cos_radius_ = 1.0f, sun_sin_radius_ = 0.0f;
  std::vector<Vec3f> sun_disc_;  // radiance by mu (the cosine on the solar surface), 0 to 1
  Vec3f sky_irradiance_;
  Vec3f below_horizon_;
  Vec3f mean_radiance_;
  // Spectral: the Hosek-Wilkie sky at its 11 wavelengths, and per bin the two of them it
  // interpolates and their weights (linear interpolation averaged over the bin; past 720 nm
  // the last wavelength times the near-infrared model: a weight on it alone).
  struct BinSource {
    int first = 0;  // the bin = w0 x channel[first] + w1 x channel[first + 1]
    float w0 = 0.0f, w1 = 0.0f;
  };
  std::unique_ptr<HosekWilkieSky> spectral_sky_;
  std::array<BinSource, kSpectrumBins> sky_bins_{};
  Spectrum sun_spectrum_, below_horizon_spectrum_;
  float sun_luminance_ = 0.0f;  // of sun_spectrum_
  DirectionTable table_;        // sampling: luminance x solid angle
};

// Irradiance from the sun on a surface facing it (lux-scaled Rec. 709) under `sky`'s model:
// the Hosek-Wilkie solar radiance integrated over a disc of `angular_radius` and against the
// CIE functions; Preetham's sun (128 klx outside the atmosphere, Rayleigh and aerosol
// extinction by Angstrom turbidity from Preetham's relation, Kasten-Young air mass); or, for
// the gradient sky, Sun's default; for the one atmosphere, Thuillier's spectrum above it at
// `earth_sun_distance` (AU), whatever the elevation above the horizon.
Vec3f sun_irradiance(const Sky& sky, double elevation_deg, double angular_radius,
                     double earth_sun_distance = 1.0);

}  // namespace landsim::renderer
