#pragma once
// From photon radiance to digital numbers (docs/SENSOR.md "Signal and noise"): electrons from
// the photon radiance through the pixel's etendue, the optics' transmittance, the quantum
// efficiency and the exposure time; dark current; Poisson shot noise of both; Gaussian read
// noise; the full well; the gain; the black level; quantisation to the ADC's bits. The noise
// comes from a seed of its own, so an image can be re-noised without tracing it again.
#include <cstdint>
#include <string>
#include <vector>

#include "renderer/sensor/sensor_model.h"

namespace landsim::renderer {

// The mean electrons of a pixel of photon radiance `photons` (photons s^-1 m^-2 sr^-1):
// photons x electrons_per_photon_radiance x t + dark current x t, before noise and the well.
double mean_electrons(double photons, double exposure_s, const SensorModel& m);

// The exposure that puts the 99th percentile of the channels' pixels (the brightest channel's)
// at 80% of the full well; `planes`: each channel's photon radiance.
double auto_exposure_time(const std::vector<const std::vector<float>*>& planes,
                          const SensorModel& m);

// One channel's digital numbers, row-major. Each row draws its noise from its own generator,
// seeded by the model's noise seed, `image` (which image of a set), the channel and the row:
// the same numbers on any thread count.
std::vector<std::uint16_t> digitise(const std::vector<float>& photons, int width, int height,
                                    double exposure_s, const SensorModel& m,
                                    const std::string& image, int channel);

}  // namespace landsim::renderer
