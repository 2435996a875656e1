// A sensor band's response CSV ([[bands]] response files, docs/SCENARIO.md), then the band
// it makes.
#include "fuzz/fuzz_input.h"
#include "renderer/spectra/sensor_band.h"
#include "scenes/scenario/sensor_bands.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return landsim::fuzz::refused_or_read([&] {
    const auto points =
        landsim::scenes::parse_band_response(landsim::fuzz::text_of(data, size), "fuzz.csv");
    landsim::renderer::sensor_band("fuzz", points);
  });
}
