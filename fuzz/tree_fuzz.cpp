// Tree generation from fuzzed species that the readers accept: every value within its
// documented range, so generation must end (a tree, or the explosion guards' refusal)
// within the run's time and memory bounds.
#include "fuzz/fuzz_input.h"
#include "trees/species.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return landsim::fuzz::refused_or_read([&] {
    const landsim::trees::Species species =
        landsim::trees::parse_species_toml(landsim::fuzz::text_of(data, size), "fuzz.toml");
    landsim::trees::generate(species, {.seed = 1, .quality = 0.5});
  });
}
