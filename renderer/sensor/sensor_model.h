#pragma once
// A camera's sensor (docs/SENSOR.md): what turns the photon radiance the renderer measures in
// each channel into electrons and digital numbers. Plain data; the loader checks the ranges.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "renderer/sensor/vignetting.h"

namespace landsim::renderer {

// A channel: a spectral response rendered as a photon-radiance layer "photons.<name>".
struct SensorChannel {
  std::string name;
  std::string definition;      // "preset rgb R", or "response <file>": what was rendered
  double wavelength_nm = 0.0;  // the response's centroid, for diffraction
};

struct SensorModel {
  std::vector<SensorChannel> channels;
  double quantum_efficiency = 0.6;        // electrons per photon, at the response's peak
  double pixel_pitch_um = 3.45;           // square pixels, 100% fill factor
  std::optional<double> exposure_time_s;  // empty: automatic (auto_exposure_time)
  double f_number = 4.0;
  double transmittance = 1.0;   // of the optics
  double gain_e_per_dn = 2.44;  // electrons per digital number (from `iso` when given)
  std::optional<double> iso;    // ISO 100 puts the full well at full scale
  double full_well_e = 10000.0;
  double read_noise_e = 2.4;  // standard deviation, electrons
  double dark_current_e_per_s = 1.0;
  int adc_bits = 12;           // 8 to 16
  int black_level_dn = 0;      // the DN of no signal
  double blur_sigma_um = 0.0;  // Gaussian defocus or jitter, standard deviation
  VignettingModel vignetting;  // none by default: an image-space telecentric lens
  std::uint64_t noise_seed = 1;
};

// The largest digital number: 2^adc_bits - 1.
int max_dn(const SensorModel& m);
// Electrons per digital number: gain_e_per_dn, or from `iso`: the full well over the range
// above the black level at ISO 100, divided by iso / 100.
double gain_e_per_dn(const SensorModel& m);
// A pixel's etendue through the lens, m^2 sr: its area times pi / (4 N^2), the solid angle
// of the exit pupil's cone seen from the pixel (object at infinity, on axis).
double pixel_etendue(const SensorModel& m);
// Electrons a second per unit photon radiance (photons s^-1 m^-2 sr^-1):
// etendue x transmittance x quantum efficiency.
double electrons_per_photon_radiance(const SensorModel& m);

}  // namespace landsim::renderer
