// An image set's manifest.json as `landsim compare` reads it (exporters/image_set_compare),
// against itself.
#include "exporters/image_set_compare.h"
#include "fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto file = landsim::fuzz::input_file(data, size, "set/manifest.json");
  return landsim::fuzz::refused_or_read(
      [&] { landsim::exporters::compare_image_sets(file.parent_path(), file.parent_path(), {}); });
}
