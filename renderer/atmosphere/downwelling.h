#pragma once
// The downwelling irradiance (docs/SENSOR.md "Irradiance and reflectance"): what lights an
// unobstructed horizontal surface at a height, as the path tracer lights it: the sun's beam
// on the surface and the sky's radiance over the upper hemisphere, each through the haze
// between the surface and the top of the atmosphere. The reference a reflectance factor
// pi L / E is taken against.
#include "renderer/scene.h"
#include "renderer/spectra/spectrum.h"

namespace landsim::renderer {

struct Downwelling {
  Spectrum direct;   // the sun's, W m^-2 nm^-1
  Spectrum diffuse;  // the sky's
  Spectrum total() const { return direct + diffuse; }
};

// At scene-frame height `z` (haze thins with height; without haze every height is alike).
Downwelling downwelling_irradiance(const Scene& scene, double z);

}  // namespace landsim::renderer
