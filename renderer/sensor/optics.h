#pragma once
// The optics in front of the sensor (docs/SENSOR.md "Optics"): a point-spread function from
// diffraction at the aperture (the Airy pattern of the f-number at a channel's wavelength),
// an optional Gaussian (defocus, jitter), and the pixel's own square aperture. Their
// modulation transfer functions multiply. The render already integrates each pixel over its
// square (box-filtered samples), so apply_optics applies diffraction and the Gaussian alone.
#include <vector>

#include "renderer/sensor/sensor_model.h"

namespace landsim::renderer {

// MTFs at a spatial frequency in cycles per pixel (along one axis for the pixel's box).
// Diffraction of a circular aperture: 2/pi (acos x - x sqrt(1 - x^2)), x = f / f_c, the
// cut-off f_c = pitch / (lambda N).
double diffraction_mtf(double cycles_per_pixel, double wavelength_nm, const SensorModel& m);
// exp(-2 pi^2 sigma^2 f^2), sigma in pixels.
double blur_mtf(double cycles_per_pixel, const SensorModel& m);
// |sin(pi f) / (pi f)|: a square pixel of 100% fill factor.
double pixel_mtf(double cycles_per_pixel);
// Their product along a pixel row.
double system_mtf(double cycles_per_pixel, double wavelength_nm, const SensorModel& m);
// The frequency where system_mtf falls to one half, cycles per pixel.
double mtf50(double wavelength_nm, const SensorModel& m);

// Convolves a channel's plane (width x height, row-major) with the diffraction and Gaussian
// PSFs: multiplied by their transfer function in the frequency domain (kissfft), the image
// mirrored at its edges first so that nothing wraps round. Exact for the sampled image up to
// the Nyquist frequency.
void apply_optics(std::vector<float>& plane, int width, int height, double wavelength_nm,
                  const SensorModel& m);

}  // namespace landsim::renderer
