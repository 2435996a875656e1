#include "discover_command.h"

#include <fmt/format.h>
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <iostream>

#include "core/atomic_file.h"
#include "core/counter_rng.h"
#include "exporters/contact_sheet.h"
#include "renderer/output/image_output.h"
#include "scenario_input.h"
#include "scenes/scenario/scenario.h"
#include "trees/harmonic/parameters.h"
#include "trees/species.h"

namespace landsim::app {

CLI::App* add_discover_command(CLI::App& app, DiscoverArgs& args) {
  CLI::App* cmd = app.add_subcommand(
      "discover",
      "Sample trees from the harmonic core's parameter space and render a contact sheet");
  cmd->add_option("--count", args.count, "Trees to sample")
      ->check(CLI::Range(1, 400))
      ->capture_default_str();
  cmd->add_option("--out", args.out, "The contact sheet (PNG)")->required();
  cmd->add_option("--seed", args.seed, "Sampling seed")->capture_default_str();
  cmd->add_option("--tile", args.tile, "Tile size in pixels")
      ->check(CLI::Range(16, 2048))
      ->capture_default_str();
  add_spp_option(*cmd, args.spp);
  cmd->add_flag("--json", args.json, "Print one JSON object on stdout");
  return cmd;
}

namespace {

// Tile k's species: parameters uniform between each one's discovery bounds.
trees::Species sampled_species(std::uint64_t seed, int k) {
  trees::Species s;
  s.name = fmt::format("discovered_{:03d}", k);
  s.parameters = trees::harmonic::sample_discovery(hash_combine(mix64(seed), k));
  return s;
}

// Written like any species file, so that a tile one likes can be used (and edited).
void write_species_file(const trees::Species& s, const std::filesystem::path& path) {
  AtomicFile file(path);
  {
    std::ofstream out(file.temp_path());
    out << "# Sampled by landsim discover; the layout is in docs/HARMONIC.md.\n"
        << "core = \"harmonic\"\nname = \"" << s.name << "\"\n"
        << trees::harmonic::format_parameters(std::get<trees::harmonic::Parameters>(s.parameters));
  }
  file.commit();
}

}  // namespace

int run_discover(const DiscoverArgs& args) {
  // The sheet is one film: refuse sizes that could not be held, before any work.
  const int columns = std::min(6, args.count);
  scenes::check_image_size(columns * args.tile, (args.count + columns - 1) / columns * args.tile,
                           "--count/--tile");
  const std::filesystem::path out(args.out);
  const std::filesystem::path dir = out.parent_path() / (out.stem().string() + "_species");
  std::filesystem::create_directories(dir);
  std::vector<trees::TreeGeometry> geometry;
  nlohmann::json tiles = nlohmann::json::array();
  for (int k = 0; k < args.count; ++k) {
    const trees::Species s = sampled_species(args.seed, k);
    const trees::Tree tree = trees::generate(s, {.seed = static_cast<std::uint64_t>(k) + 1});
    geometry.push_back(tree.geometry);
    const std::filesystem::path file = dir / (s.name + ".toml");
    write_species_file(s, file);
    tiles.push_back({{"species", file.string()},
                     {"height_m", tree.stats.height},
                     {"crown_radius_m", tree.stats.crown_radius},
                     {"leaves", tree.stats.leaves}});
  }
  exporters::ContactSheetOptions o;
  o.tile = args.tile;
  o.spp = args.spp;
  o.seed = args.seed;
  const renderer::Film sheet = exporters::render_contact_sheet(geometry, o);
  renderer::write_preview_png(sheet, out, std::nullopt);
  if (args.json) {
    std::cout << nlohmann::json{{"sheet", out.string()},
                                {"columns", std::min(6, args.count)},
                                {"tiles", tiles}}
                     .dump()
              << "\n";
  } else {
    std::cout << fmt::format("{}: {} trees, species files in {}\n", out.string(), args.count,
                             dir.string());
  }
  return 0;
}

}  // namespace landsim::app
