// A user's POV-Ray scene as `crosscheck --pov` reads its camera (exporters/pov_camera).
#include "exporters/pov_camera.h"
#include "fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto file = landsim::fuzz::input_file(data, size, "scene.pov");
  return landsim::fuzz::refused_or_read([&] { landsim::exporters::read_pov_camera(file, 64, 36); });
}
