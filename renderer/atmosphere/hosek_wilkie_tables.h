#pragma once
// The published coefficient tables of the Hosek-Wilkie sky (2012) and solar radiance
// function (2013), release 1.4a, as compiled into the program from data/sky/ (provenance
// and BSD licence there). Read once, on first use.
#include <array>
#include <cstddef>

namespace landsim::renderer {

struct HosekWilkieTables {
  static constexpr int kChannels = 3;        // R, G, B (linear Rec. 709)
  static constexpr int kTurbidities = 10;    // 1 to 10
  static constexpr int kControlPoints = 6;   // quintic Bezier in solar elevation
  static constexpr int kParameters = 9;      // A, B, C, D, E, F, G, I, H in file order
  static constexpr int kWavelengths = 11;    // 320 to 720 nm in steps of 40
  static constexpr int kSolarSegments = 45;  // pieces in solar elevation
  static constexpr double kFirstWavelength = 320.0, kWavelengthStep = 40.0;

  // [channel][albedo 0|1][turbidity - 1][control point][parameter]
  std::array<double, kChannels * 2 * kTurbidities * kControlPoints * kParameters> coefficients;
  // [channel][albedo][turbidity - 1][control point]: the overall radiance L_M
  std::array<double, kChannels * 2 * kTurbidities * kControlPoints> radiance;
  // The same for the spectral tables: [wavelength][albedo][turbidity - 1][control point]...
  std::array<double, kWavelengths * 2 * kTurbidities * kControlPoints * kParameters>
      spectral_coefficients;
  std::array<double, kWavelengths * 2 * kTurbidities * kControlPoints> spectral_radiance;
  // [wavelength][turbidity - 1][segment][cubic, quadratic, linear, constant term]
  std::array<double, kWavelengths * kTurbidities * kSolarSegments * 4> solar;
  // [wavelength][power 0..5] of the cosine on the solar disc
  std::array<double, kWavelengths * 6> limb_darkening;

  // `spectral`: channel is a wavelength of the spectral tables, else R, G, B.
  const double* control_points(int channel, int albedo, int turbidity_index,
                               bool spectral = false) const {
    return (spectral ? spectral_coefficients.data() : coefficients.data()) +
           static_cast<std::size_t>(((channel * 2 + albedo) * kTurbidities + turbidity_index) *
                                    kControlPoints * kParameters);
  }
  const double* radiance_points(int channel, int albedo, int turbidity_index,
                                bool spectral = false) const {
    return (spectral ? spectral_radiance.data() : radiance.data()) +
           static_cast<std::size_t>(((channel * 2 + albedo) * kTurbidities + turbidity_index) *
                                    kControlPoints);
  }
  const double* solar_segment(int wavelength, int turbidity_index, int segment) const {
    return &solar[static_cast<std::size_t>(
        ((wavelength * kTurbidities + turbidity_index) * kSolarSegments + segment) * 4)];
  }
};

const HosekWilkieTables& hosek_wilkie_tables();

}  // namespace landsim::renderer
