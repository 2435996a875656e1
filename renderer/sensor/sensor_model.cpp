#include "renderer/sensor/sensor_model.h"

#include <numbers>

namespace landsim::renderer {

int max_dn(const SensorModel& m) { return (1 << m.adc_bits) - 1; }

double gain_e_per_dn(const SensorModel& m) {
  if (!m.iso) return m.gain_e_per_dn;
  const double range = static_cast<double>(max_dn(m) - m.black_level_dn);
  return m.full_well_e / range * 100.0 / *m.iso;
}

double pixel_etendue(const SensorModel& m) {
  const double pitch = m.pixel_pitch_um * 1e-6;
  return pitch * pitch * std::numbers::pi / (4.0 * m.f_number * m.f_number);
}

double electrons_per_photon_radiance(const SensorModel& m) {
  return pixel_etendue(m) * m.transmittance * m.quantum_efficiency;
}

}  // namespace landsim::renderer
