// Scenario TOML, its relative paths resolved in a small folder of real inputs laid out once
// (a species file of each core, an elevation grid, a feature map, a class mapping), so that
// a scenario naming them is read through as far as a user's would be.
#include <filesystem>
#include <fstream>

#include "fuzz/fuzz_input.h"
#include "scenes/scenario/scenario.h"

namespace {

std::string g_base;

void copy_in(const std::filesystem::path& dir, const std::string& relative) {
  const std::filesystem::path from = std::filesystem::path(LANDSIM_SOURCE_DIR) / relative;
  std::filesystem::copy_file(from, dir / from.filename(),
                             std::filesystem::copy_options::overwrite_existing);
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  const auto dir = std::filesystem::temp_directory_path() / "landsim_scenario_fuzz";
  std::filesystem::create_directories(dir);
  for (const char* f : {"data/species/quaking_aspen.toml", "data/species/quaking_aspen.xml",
                        "data/species/graph_bush.toml", "data/species/so_upright.toml",
                        "data/species/harmonic_juniper.toml", "data/species/london_plane.toml",
                        "data/terrain/volcano.asc", "scenes/examples/kagwene_classes.toml"})
    copy_in(dir, f);
  g_base = dir.string();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return landsim::fuzz::refused_or_read([&] {
    landsim::scenes::parse_scenario(landsim::fuzz::text_of(data, size), "fuzz.toml", g_base);
  });
}
