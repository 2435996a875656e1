#include "info_command.h"

#include <fmt/format.h>
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <iostream>

#include "scenario_input.h"
#include "scenes/builder/memory_estimate.h"

namespace landsim::app {

CLI::App* add_info_command(CLI::App& app, InfoArgs& args) {
  CLI::App* cmd = app.add_subcommand(
      "info", "Describe a scenario's scene without building it: expected trees, triangles, memory");
  cmd->add_option("scenario", args.scenario, "Scenario TOML file (default: the embedded scene)");
  cmd->add_flag("--json", args.json, "Print one JSON object on stdout");
  add_set_option(*cmd, args.sets);
  return cmd;
}

int run_info(const InfoArgs& args) {
  const scenes::Scenario scenario = scenario_or_default(args.scenario, args.sets);
  const scenes::MemoryEstimate e = scenes::estimate_memory(scenario);
  const auto count = [](double n) { return static_cast<std::size_t>(std::llround(n)); };
  if (args.json) {
    std::cout << scenes::estimate_json(scenario, e).dump() << "\n";
    return 0;
  }
  std::cout << fmt::format("{}\n  trees (expected)    {}\n", scenario.source, count(e.instances));
  for (const auto& [name, n] : e.instances_per_species)
    std::cout << fmt::format("    {:<20}{}\n", name, count(n));
  std::cout << fmt::format(
      "  unique variants     {}\n  triangles stored    {}\n  triangles instanced {}\n"
      "  grass tiles         {}\n  memory estimate     {:.0f} MB at the peak\n",
      e.unique_variants, count(e.triangles_stored), count(e.triangles_instanced), e.grass_tiles,
      static_cast<double>(e.total_bytes()) / 1e6);
  std::cout << fmt::format("    {:<38}{:>6.0f} MB\n", "program",
                           static_cast<double>(e.program_bytes) / 1e6);
  for (const scenes::MemoryPart& p : e.parts)
    std::cout << fmt::format("    {:<38}{:>6.0f} MB\n", p.name, static_cast<double>(p.bytes) / 1e6);
  return 0;
}

}  // namespace landsim::app
