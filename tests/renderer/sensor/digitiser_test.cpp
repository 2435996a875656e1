// The sensor's signal chain (docs/SENSOR.md "Signal and noise"): photon transfer on a flat
// field, the radiometric formula, the well, the gain from ISO and the noise seed.
#include "renderer/sensor/digitiser.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>
#include <numbers>

namespace landsim::renderer {
namespace {

constexpr int kSide = 256;

SensorModel test_sensor() {
  SensorModel m;
  m.channels = {{"G", "test", 550.0}};
  m.quantum_efficiency = 0.5;
  m.pixel_pitch_um = 5.0;
  m.f_number = 2.8;
  m.transmittance = 0.9;
  m.gain_e_per_dn = 2.0;
  m.full_well_e = 40000.0;
  m.read_noise_e = 10.0;
  m.dark_current_e_per_s = 0.0;
  m.adc_bits = 16;
  m.black_level_dn = 200;  // keeps the read noise clear of zero
  return m;
}

struct Moments {
  double mean = 0.0, variance = 0.0;
};

Moments moments(const std::vector<std::uint16_t>& dn) {
  double sum = 0.0, squares = 0.0;
  for (const std::uint16_t v : dn) {
    sum += v;
    squares += static_cast<double>(v) * v;
  }
  const double n = static_cast<double>(dn.size());
  const double mean = sum / n;
  return {mean, (squares - n * mean * mean) / (n - 1.0)};
}

// The photon radiance of a flat field: photons s-1 m-2 sr-1.
constexpr double kFlatField = 3e19;

// The electrons the test's own radiometry expects: L x A x pi / (4 N^2) x tau x QE x t.
double expected_electrons(const SensorModel& m, double photons, double t) {
  const double area = std::pow(m.pixel_pitch_um * 1e-6, 2.0);
  return photons * area * std::numbers::pi / (4.0 * m.f_number * m.f_number) * m.transmittance *
         m.quantum_efficiency * t;
}

TEST(Digitiser, PhotonTransferFollowsShotAndReadNoise) {
  const SensorModel m = test_sensor();
  const std::vector<float> field(kSide * kSide, static_cast<float>(kFlatField));
  // Five exposures from a few hundred electrons to most of the well.
  std::vector<Moments> points;
  for (const double fraction : {0.02, 0.1, 0.25, 0.5, 0.8}) {
    const double t = fraction * m.full_well_e / expected_electrons(m, kFlatField, 1.0);
    Moments p = moments(digitise(field, kSide, kSide, t, m, "flat", 0));
    p.mean -= m.black_level_dn;
    points.push_back(p);
  }
  // Least squares: variance = slope x mean + intercept.
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (const Moments& p : points) {
    sx += p.mean;
    sy += p.variance;
    sxx += p.mean * p.mean;
    sxy += p.mean * p.variance;
  }
  const double n = static_cast<double>(points.size());
  const double slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
  const double intercept = (sy - slope * sx) / n;
  // Shot noise: var(e) = mean(e), so in DN the slope is 1 / gain; read noise and the
  // quantisation's uniform error (1/12 DN^2) make the intercept.
  const double gain = m.gain_e_per_dn;
  EXPECT_NEAR(slope * gain, 1.0, 0.05);
  const double floor = m.read_noise_e * m.read_noise_e / (gain * gain) + 1.0 / 12.0;
  EXPECT_NEAR(intercept / floor, 1.0, 0.05) << intercept << " against " << floor;
}

TEST(Digitiser, MeanMatchesTheRadiometricFormula) {
  SensorModel m = test_sensor();
  m.dark_current_e_per_s = 50.0;
  const std::vector<float> field(kSide * kSide, static_cast<float>(kFlatField));
  const double t = 0.0005;  // about 17,000 electrons: within the well
  const Moments p = moments(digitise(field, kSide, kSide, t, m, "flat", 0));
  const double electrons = expected_electrons(m, kFlatField, t) + 50.0 * t;
  const double expected = electrons / m.gain_e_per_dn + m.black_level_dn;
  EXPECT_NEAR(p.mean / expected, 1.0, 0.01) << p.mean << " against " << expected;
  EXPECT_NEAR(mean_electrons(kFlatField, t, m), electrons, 1e-6 * electrons);
}

TEST(Digitiser, TheWellAndTheAdcClip) {
  SensorModel m = test_sensor();
  m.read_noise_e = 0.0;
  m.black_level_dn = 0;
  const std::vector<float> field(64 * 64, static_cast<float>(kFlatField * 1e3));
  // The well (40000 e-, 20000 DN at 2 e-/DN) clips first.
  for (const std::uint16_t v : digitise(field, 64, 64, 0.01, m, "bright", 0)) ASSERT_EQ(v, 20000);
  // With a smaller ADC the top of its range does.
  m.adc_bits = 12;
  for (const std::uint16_t v : digitise(field, 64, 64, 0.01, m, "bright", 0)) ASSERT_EQ(v, 4095);
}

TEST(Digitiser, IsoSetsTheGainFromTheWell) {
  SensorModel m = test_sensor();
  m.adc_bits = 12;
  m.black_level_dn = 95;
  m.iso = 400.0;
  // ISO 100 spans the well over the range above the black level; ISO 400 a quarter of it.
  EXPECT_NEAR(gain_e_per_dn(m), 40000.0 / 4000.0 / 4.0, 1e-12);
  m.iso.reset();
  EXPECT_EQ(gain_e_per_dn(m), 2.0);
}

TEST(Digitiser, NoiseSeedAloneChangesTheNoise) {
  SensorModel m = test_sensor();
  const std::vector<float> field(kSide * kSide, static_cast<float>(kFlatField));
  const auto a = digitise(field, kSide, kSide, 0.003, m, "view", 0);
  EXPECT_EQ(a, digitise(field, kSide, kSide, 0.003, m, "view", 0));
  std::vector<std::uint16_t> single_thread;
  {
    const tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
    single_thread = digitise(field, kSide, kSide, 0.003, m, "view", 0);
  }
  EXPECT_EQ(a, single_thread);
  EXPECT_NE(a, digitise(field, kSide, kSide, 0.003, m, "view", 1));   // another channel
  EXPECT_NE(a, digitise(field, kSide, kSide, 0.003, m, "other", 0));  // another image
  m.noise_seed = 2;
  const auto b = digitise(field, kSide, kSide, 0.003, m, "view", 0);
  EXPECT_NE(a, b);
  // ...and nothing else: the means agree within their noise.
  EXPECT_NEAR(moments(a).mean, moments(b).mean,
              5.0 * std::sqrt(moments(a).variance / static_cast<double>(a.size())));
}

TEST(Digitiser, AutoExposureFillsEightyPercentOfTheWell) {
  SensorModel m = test_sensor();
  std::vector<float> ramp(100 * 100);
  for (std::size_t i = 0; i < ramp.size(); ++i)
    ramp[i] =
        static_cast<float>(kFlatField * static_cast<double>(i) / static_cast<double>(ramp.size()));
  const double t = auto_exposure_time({&ramp}, m);
  // The 99th percentile of the ramp at 80% of the well.
  EXPECT_NEAR(expected_electrons(m, kFlatField * 0.99, t) / m.full_well_e, 0.8, 0.002);
}

}  // namespace
}  // namespace landsim::renderer
