#pragma once
// One ray segment through the haze (renderer/atmosphere/medium.h), as the path tracer takes
// it: its transmittance, and a scattering point drawn on it. Every segment that the haze
// touches gets a point, drawn in [0, t] in proportion to extinction x transmittance, where
// the sun and sky are estimated (next-event estimation: the haze's veil on every camera ray);
// the path then goes on from that point with probability q (the segment's mean scattered
// share) or through to the surface or sky with 1 - q. Unbiased, and the veil costs no
// more rays than single scattering did.
//
// The segment carries 32 wavelength bins whose extinctions differ (Rayleigh's fourth power,
// Angstrom's law). The point is drawn for one bin chosen at random among those an output
// sees, and weighed by the mean of every such bin's density (one-sample multiple importance
// sampling over the bins, as hero-wavelength tracers do): the weights stay bounded in the
// near infrared however long the segment.
#include <array>
#include <cstdint>

#include "core/vec3.h"
#include "renderer/atmosphere/medium.h"
#include "renderer/camera.h"
#include "renderer/spectra/spectrum.h"

namespace landsim::renderer {

struct MediumPoint {
  Vec3f position;
  // Per component, transmittance to the point x its scattering coefficient there, over the
  // point's density: the phase function's weight in each bin.
  std::array<Spectrum, kMediumComponents> weight;
  // How often a new direction from here follows each component's phase function: in
  // proportion to its weight in the bins an output sees.
  std::array<float, kMediumComponents> share{};
};

// The phase functions at p weighted per bin (what a ray scattered there carries), the pdf with
// which scatter_direction draws a direction, and a direction drawn about `d` (the travel
// direction): the component by its share (u_component), then its own phase function (u).
Spectrum phase_weight(const Medium& medium, const MediumPoint& p, float cos_theta);
float phase_pdf(const Medium& medium, const MediumPoint& p, float cos_theta);
Vec3f scatter_direction(const Medium& medium, const MediumPoint& p, const Vec3f& d,
                        float u_component, const std::array<float, 2>& u);

class MediumSegment {
 public:
  // The segment ray.origin + s ray.direction, s in [0, t]; t infinite when it leaves into
  // the sky (`ends_on_surface` false: the air's component is the sky's).
  MediumSegment(const Medium& medium, const Ray& ray, double t, bool ends_on_surface,
                const BinSet& bins);

  // Whether the haze touches the segment in a bin an output sees.
  bool scatters() const { return candidates_.count > 0; }
  const Spectrum& transmittance() const { return transmittance_; }
  // The probability that the path goes on from the scattering point.
  float continue_probability() const { return continue_; }
  // The scattering point, from two uniform numbers (bin, distance).
  MediumPoint sample(float u_bin, float u_distance) const;

 private:
  const Medium& medium_;
  Vec3 origin_, direction_;
  double t_;
  bool ends_on_surface_;
  Spectrum transmittance_;
  std::array<float, kSpectrumBins> scattered_{};  // 1 - T per bin
  const BinSet& bins_;                            // the bins worked in
  BinSet candidates_;                             // seen bins the haze touches
  float continue_ = 0.0f;
};

}  // namespace landsim::renderer
