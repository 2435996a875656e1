#include "renderer/atmosphere/sky.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "renderer/atmosphere/hosek_wilkie.h"
#include "renderer/atmosphere/preetham.h"
#include "renderer/atmosphere/standard_atmosphere.h"
#include "renderer/spectra/near_infrared.h"
#include "renderer/spectra/spectral_colour.h"

namespace landsim::renderer {
namespace {

constexpr float kPi = std::numbers::pi_v<float>;
constexpr double kCdPerKcd = 1000.0;  // Preetham's luminance unit is kcd/m2
constexpr int kSunDiscSteps = 64;     // the disc's radiance profile, by mu

float luminance(const Vec3f& c) { return 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z; }

// The integral of f(direction) over the upper hemisphere's solid angle: the midpoint rule on
// `steps` rings of theta and twice as many sectors of phi. For irradiance f is L cos.
template <typename F>
auto upper_hemisphere_integral(int steps, F&& f) {
  decltype(f(Vec3f{})) sum{};
  for (int i = 0; i < steps; ++i) {
    const float theta = 0.5f * kPi * (static_cast<float>(i) + 0.5f) / static_cast<float>(steps);
    for (int j = 0; j < 2 * steps; ++j) {
      const float phi = 2.0f * kPi * (static_cast<float>(j) + 0.5f) / static_cast<float>(2 * steps);
      sum += f(DirectionTable::direction_of(theta, phi)) * std::sin(theta);
    }
  }
  const float cell = (0.5f * kPi / static_cast<float>(steps)) * (kPi / static_cast<float>(steps));
  return sum * cell;
}

}  // namespace

namespace {

// No sky is a gradient of nothing: every direction above the horizon dark, so the sun is the
// only light (its sampling table stays valid: DirectionTable's floor keeps it uniform). The
// one atmosphere's space is as dark: its sky is the medium's light, not the sky model's.
Sky dark_if_none(Sky sky) {
  if (sky.model != SkyKind::none && sky.model != SkyKind::atmosphere) return sky;
  sky.model = SkyKind::gradient;
  sky.zenith_radiance = sky.horizon_radiance = Vec3f{};
  return sky;
}

}  // namespace

SkyModel::SkyModel(const Sky& sky, const Sun& sun, Vec3f ground_albedo, const SpectralGrid& grid)
    : sky_(dark_if_none(sky)),
      atmosphere_(sky.model == SkyKind::atmosphere),
      sun_direction_(normalize(Vec3f(sun.direction))) {
  const double elevation = std::asin(std::clamp(normalize(sun.direction).z, 0.0, 1.0));
  if (sky.model == SkyKind::preetham)
    preetham_ = std::make_unique<PreethamSky>(sun.direction, sky.turbidity);
  if (sky.model == SkyKind::hosek_wilkie)
    hosek_wilkie_ = std::make_unique<HosekWilkieSky>(elevation, sky.turbidity, Vec3(ground_albedo));
  build_sun_disc(sun, elevation);
  // E = integral over the upper hemisphere of L cos, on a fine grid.
  constexpr int kSteps = 96;
  sky_irradiance_ =
      upper_hemisphere_integral(kSteps, [&](const Vec3f& d) { return above_horizon(d) * d.z; });
  const float sun_cos = static_cast<float>(std::max(sun.direction.z, 0.0));
  const Vec3f plain_irradiance = sun.irradiance * sun_cos + sky_irradiance_;
  below_horizon_ = ground_albedo * plain_irradiance * (1.0f / kPi);
  // Upper hemisphere: its mean radiance is the integral of L over 2 pi; lower: the plain.
  const Vec3f upper =
      upper_hemisphere_integral(kSteps, [&](const Vec3f& d) { return above_horizon(d); }) *
      (1.0f / (2.0f * kPi));
  mean_radiance_ = (upper + below_horizon_) * 0.5f;
  table_ = DirectionTable([&](const Vec3f& d) { return luminance(radiance(d)); });
  build_spectra(sun, elevation, ground_albedo, grid);
}

SkyModel::~SkyModel() = default;
SkyModel::SkyModel(SkyModel&&) noexcept = default;

void SkyModel::build_sun_disc(const Sun& sun, double elevation) {
  const double r = sun.angular_radius;
  sun_cos_radius_ = static_cast<float>(std::cos(r));
  sun_sin_radius_ = static_cast<float>(std::sin(r));
  // The profile's shape: Hosek-Wilkie's limb darkening per channel, else a uniform disc.
  std::vector<Vec3> shape(kSunDiscSteps + 1, Vec3{1.0, 1.0, 1.0});
  if (hosek_wilkie_) {
    const HosekWilkieSun model(elevation, sky_.turbidity);
    for (int i = 0; i <= kSunDiscSteps; ++i)
      shape[static_cast<std::size_t>(i)] = model.radiance(static_cast<double>(i) / kSunDiscSteps);
  }
  // Scaled so that the disc gives exactly the scene's sun irradiance (which a scenario may
  // set): integral of L cos over the disc = pi sin^2 R x 2 int_0^1 L(mu) mu dmu.
  Vec3 integral{};
  for (int i = 0; i < kSunDiscSteps; ++i) {
    const double mu = (i + 0.5) / kSunDiscSteps;
    const Vec3 mid =
        (shape[static_cast<std::size_t>(i)] + shape[static_cast<std::size_t>(i + 1)]) * 0.5;
    integral += mid * (2.0 * mu / kSunDiscSteps);
  }
  integral = integral * (std::numbers::pi * std::sin(r) * std::sin(r));
  sun_disc_.resize(shape.size());
  for (std::size_t i = 0; i < shape.size(); ++i) {
    const auto channel = [&](double s, double total, float e) {
      return total > 0.0 ? static_cast<float>(s / total * e) : 0.0f;
    };
    sun_disc_[i] = {channel(shape[i].x, integral.x, sun.irradiance.x),
                    channel(shape[i].y, integral.y, sun.irradiance.y),
                    channel(shape[i].z, integral.z, sun.irradiance.z)};
  }
}

Vec3f SkyModel::sun_radiance(const Vec3f& d) const {
  const float c = dot(d, sun_direction_);
  if (c < sun_cos_radius_ || sun_sin_radius_ <= 0.0f) return {};
  const float s = std::sqrt(std::max(0.0f, 1.0f - c * c)) / sun_sin_radius_;
  const float mu = std::sqrt(std::max(0.0f, 1.0f - s * s));
  const float x = mu * kSunDiscSteps;
  const int i = std::min(static_cast<int>(x), kSunDiscSteps - 1);
  const float f = x - static_cast<float>(i);
  return sun_disc_[static_cast<std::size_t>(i)] * (1.0f - f) +
         sun_disc_[static_cast<std::size_t>(i + 1)] * f;
}

Vec3f SkyModel::above_horizon(const Vec3f& d) const {
  if (hosek_wilkie_) return Vec3f(hosek_wilkie_->radiance_cos(d.z, dot(d, sun_direction_)));
  if (preetham_) return Vec3f(preetham_->radiance_kcd(Vec3(d)) * kCdPerKcd);
  // The exponent keeps a bright band near the horizon, as haze-free skies show.
  const float t = std::pow(std::clamp(d.z, 0.0f, 1.0f), 0.4f);
  return sky_.horizon_radiance * (1.0f - t) + sky_.zenith_radiance * t;
}

namespace {

// The sun's irradiance at one wavelength from the limb-darkened disc of `radius`:
// pi sin^2 R x 2 int_0^1 L(mu) mu dmu.
double disc_irradiance(const HosekWilkieSun& sun, double wavelength_nm, double radius) {
  constexpr int kSteps = 16;
  double sum = 0.0;
  for (int i = 0; i < kSteps; ++i) {
    const double mu = (i + 0.5) / kSteps;
    sum += sun.spectral_radiance(wavelength_nm, mu) * mu / kSteps;
  }
  return 2.0 * std::numbers::pi * std::sin(radius) * std::sin(radius) * sum;
}

}  // namespace

void SkyModel::build_spectra(const Sun& sun, double elevation, Vec3f ground_albedo,
                             const SpectralGrid& grid) {
  const Spectrum ground = reflectance_spectrum(ground_albedo);
  if (hosek_wilkie_) {
    const NearInfrared infrared(elevation, sky_.turbidity);
    constexpr int kWavelengths = 11;
    constexpr double kFirst = 320.0, kStep = 40.0;
    // Hosek-Wilkie's ground albedo at its wavelengths: the bin's that holds each.
    std::array<double, kWavelengths> albedo{};
    for (int w = 0; w < kWavelengths; ++w) {
      const int k =
          std::clamp(static_cast<int>((kFirst + kStep * w - kFirstWavelength) / kBinWidth), 0,
                     kSpectrumBins - 1);
      albedo[static_cast<std::size_t>(w)] = ground[k];
    }
    spectral_sky_ = std::make_unique<HosekWilkieSky>(
        HosekWilkieSky::spectral(elevation, sky_.turbidity, albedo));
    // Each bin: the tables' linear interpolation averaged over its 1 nm steps; past 720 nm,
    // the last wavelength times the near-infrared model's ratio. A 20 nm bin lies within one
    // 40 nm interval of the tables, so two wavelengths serve each.
    const int steps = static_cast<int>(kBinWidth);
    for (int k = 0; k < kSpectrumBins; ++k) {
      std::array<double, kWavelengths> row{};
      for (int i = 0; i < steps; ++i) {
        const double nm = bin_start(k) + i + 0.5;
        if (nm > NearInfrared::kJoin) {
          row[kWavelengths - 1] += infrared.sky_ratio(nm) / steps;
          continue;
        }
        const double position = (nm - kFirst) / kStep;
        const int w = std::min(static_cast<int>(position), kWavelengths - 2);
        const double f = position - w;
        row[static_cast<std::size_t>(w)] += (1.0 - f) / steps;
        row[static_cast<std::size_t>(w + 1)] += f / steps;
      }
      int first = kWavelengths - 2;
      for (int w = 0; w < kWavelengths - 1; ++w)
        if (row[static_cast<std::size_t>(w)] > 0.0) {
          first = w;
          break;
        }
      sky_bins_[static_cast<std::size_t>(k)] = {
          first, static_cast<float>(row[static_cast<std::size_t>(first)]),
          static_cast<float>(row[static_cast<std::size_t>(first + 1)])};
    }
    const HosekWilkieSun model(elevation, sky_.turbidity);
    sun_spectrum_ = bin_average([&](double nm) {
      const double e =
          disc_irradiance(model, std::min(nm, NearInfrared::kJoin), sun.angular_radius);
      return nm > NearInfrared::kJoin ? e * infrared.sun_ratio(nm) : e;
    });
    // The scene's sun irradiance (which a scenario may set) decides its colour: the model's
    // spectrum times the upsampled ratio of the two colours (a flat 1 when they agree),
    // repeated until the colour is met (a product of spectra is not the product of colours).
    const auto ratio = [](float want, float have) { return have > 0.0f ? want / have : 0.0f; };
    for (int pass = 0; pass < 4; ++pass) {
      const Vec3f rgb = spectrum_to_rgb(sun_spectrum_);
      sun_spectrum_ *=
          reflectance_spectrum({ratio(sun.irradiance.x, rgb.x), ratio(sun.irradiance.y, rgb.y),
                                ratio(sun.irradiance.z, rgb.z)});
    }
  } else if (atmosphere_) {
    // The sun above the atmosphere: the medium takes out what it extinguishes on the way.
    sun_spectrum_ = solar_irradiance_toa(sun.earth_sun_distance, grid);
  } else {
    sun_spectrum_ = emission_spectrum(sun.irradiance);
  }
  sun_luminance_ = luminance(spectrum_to_rgb(sun_spectrum_));
  // The sunlit plain below the horizon, as for RGB: its albedo x (sun + sky) / pi.
  const Spectrum sky_irradiance = upper_hemisphere_integral(
      32, [&](const Vec3f& d) { return above_horizon_spectral(d) * d.z; });
  const float sun_cos = static_cast<float>(std::max(sun.direction.z, 0.0));
  below_horizon_spectrum_ = ground * (sun_spectrum_ * sun_cos + sky_irradiance) * (1.0f / kPi);
}

Spectrum SkyModel::above_horizon_spectral(const Vec3f& d) const {
  if (!spectral_sky_) return emission_spectrum(above_horizon(d));
  double channels[11];
  spectral_sky_->channels_cos(d.z, dot(d, sun_direction_), channels);
  Spectrum out;
  for (int k = 0; k < kSpectrumBins; ++k) {
    const BinSource& b = sky_bins_[static_cast<std::size_t>(k)];
    out[k] = b.w0 * static_cast<float>(channels[b.first]) +
             b.w1 * static_cast<float>(channels[b.first + 1]);
  }
  return out;
}

Spectrum SkyModel::spectral_radiance(const Vec3f& direction) const {
  return direction.z >= 0.0f ? above_horizon_spectral(direction) : below_horizon_spectrum_;
}

Spectrum SkyModel::sun_spectral_radiance(const Vec3f& direction) const {
  // The disc's luminance profile for every wavelength: the spectrum of its whole irradiance
  // times the share of it this point of the disc carries.
  const float y = luminance(sun_radiance(direction));
  if (y <= 0.0f || sun_luminance_ <= 0.0f) return {};
  return sun_spectrum_ * (y / sun_luminance_);
}

namespace {

// The mean of `above` (a direction's radiance, any type) over the horizon band at the azimuth
// of `d`: elevations 0 to 2 degrees, 8 samples.
template <typename Above>
auto horizon_band_mean(const Vec3f& d, Above&& above) {
  constexpr int kSamples = 8;
  constexpr float kBand = 2.0f * kPi / 180.0f;
  const float h = std::sqrt(d.x * d.x + d.y * d.y);
  const Vec3f level = h > 0.0f ? Vec3f{d.x / h, d.y / h, 0.0f} : Vec3f{1.0f, 0.0f, 0.0f};
  decltype(above(d)) sum{};
  for (int i = 0; i < kSamples; ++i) {
    const float e = kBand * (static_cast<float>(i) + 0.5f) / kSamples;
    sum += above(level * std::cos(e) + Vec3f{0.0f, 0.0f, std::sin(e)});
  }
  return sum * (1.0f / kSamples);
}

}  // namespace

Spectrum SkyModel::horizon_band_spectral(const Vec3f& d) const {
  return horizon_band_mean(d, [&](const Vec3f& v) { return above_horizon_spectral(v); });
}

Vec3f SkyModel::horizon_band_radiance(const Vec3f& d) const {
  return horizon_band_mean(d, [&](const Vec3f& v) { return above_horizon(v); });
}

Vec3f SkyModel::radiance(const Vec3f& direction) const {
  return direction.z >= 0.0f ? above_horizon(direction) : below_horizon_;
}

Vec3f SkyModel::sample(float u1, float u2, float& pdf) const { return table_.sample(u1, u2, pdf); }

float SkyModel::pdf(const Vec3f& d) const { return table_.pdf(d); }

namespace {

Vec3f preetham_sun_irradiance(double elevation_deg, double turbidity) {
  const double zenith = 90.0 - elevation_deg;
  const double air_mass = 1.0 / (std::cos(zenith * std::numbers::pi / 180.0) +
                                 0.50572 * std::pow(96.07995 - zenith, -1.6364));
  // Rayleigh optical depth at 680, 550, 440 nm; aerosols by Angstrom's law with Preetham's beta(T).
  const double rayleigh[3] = {0.043, 0.097, 0.235};
  const double wavelength_um[3] = {0.68, 0.55, 0.44};
  const double beta = std::max(0.0, 0.04608 * turbidity - 0.04586);
  const double e0 = 128000.0;  // extraterrestrial illuminance, lux
  double e[3];
  for (int c = 0; c < 3; ++c) {
    const double aerosol = beta * std::pow(wavelength_um[c], -1.3);
    e[c] = e0 * std::exp(-air_mass * (rayleigh[c] + aerosol));
  }
  return {static_cast<float>(e[0]), static_cast<float>(e[1]), static_cast<float>(e[2])};
}

}  // namespace

Vec3f sun_irradiance(const Sky& sky, double elevation_deg, double angular_radius,
                     double earth_sun_distance) {
  if (elevation_deg <= 0.0) return {};
  switch (sky.model) {
    case SkyKind::atmosphere:
      return spectrum_to_rgb(solar_irradiance_toa(earth_sun_distance));
    case SkyKind::hosek_wilkie:
      return Vec3f(HosekWilkieSun(elevation_deg * std::numbers::pi / 180.0, sky.turbidity)
                       .irradiance(angular_radius));
    case SkyKind::preetham:
      return preetham_sun_irradiance(elevation_deg, sky.turbidity);
    case SkyKind::gradient:
    case SkyKind::none:
      break;
  }
  return Sun{}.irradiance;
}

}  // namespace landsim::renderer
