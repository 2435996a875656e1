// Arbaro XML species files (Weber & Penn).
#include "fuzz/fuzz_input.h"
#include "trees/species.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return landsim::fuzz::refused_or_read(
      [&] { landsim::trees::parse_species(landsim::fuzz::text_of(data, size), "fuzz.xml"); });
}
