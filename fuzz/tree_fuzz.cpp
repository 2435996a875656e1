// Tree generation from fuzzed species that the readers accept: every value within its
// documented range, so generation must end (a tree, or the explosion guards' refusal)
// within the run's time and memory bounds.
//
// Grown on one core: the self-organising core's marker passes run on every core, and under
// libFuzzer's comparison tracing (shared tables every thread writes) two threads ran five times
// slower than one (so_shedding 40.5 s against 8.2 s under ASan, past the 10 s timeout). The
// tree is the same bits on any number of cores (SelfOrganizing.TheSameTreeOnOneCoreAsOnTwo).
#include <tbb/task_arena.h>

#include "fuzz/fuzz_input.h"
#include "trees/species.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static tbb::task_arena one_core(1);
  return landsim::fuzz::refused_or_read([&] {
    const landsim::trees::Species species =
        landsim::trees::parse_species_toml(landsim::fuzz::text_of(data, size), "fuzz.toml");
    one_core.execute([&] { landsim::trees::generate(species, {.seed = 1, .quality = 0.5}); });
  });
}
