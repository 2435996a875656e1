// Class-mapping TOML (land-cover class -> species bits and grass).
#include "featuremaps/class_mapping.h"
#include "fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return landsim::fuzz::refused_or_read([&] {
    landsim::featuremaps::parse_class_mapping(landsim::fuzz::text_of(data, size), "fuzz.toml");
  });
}
