#include "tree_command.h"

#include <fmt/format.h>
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <malloc.h>

#include <chrono>
#include <fstream>
#include <iostream>

#include "core/atomic_file.h"
#include "core/input_error.h"
#include "exporters/obj_export.h"
#include "scenes/scenario/scenario.h"
#include "trees/self_organizing/simulation.h"
#include "trees/species.h"

namespace landsim::app {

CLI::App* add_tree_command(CLI::App& app, TreeArgs& args) {
  CLI::App* cmd = app.add_subcommand("tree", "Generate one tree and print its statistics");
  cmd->add_option("species", args.species, "Species file (.toml, or Arbaro .xml)")->required();
  cmd->add_option("--seed", args.seed, "Variant seed")->capture_default_str();
  cmd->add_option("--time", args.time, "Time in seconds, for wind sway")
      ->check(CLI::Range(0.0, 1e9));
  cmd->add_option("--wind", args.wind, "Wind speed (as [wind] speed)")
      ->check(CLI::Range(0.0, scenes::kMaxWindSpeed));
  cmd->add_option("--gust", args.gust, "Wind gust speed (as [wind] gust)")
      ->check(CLI::Range(0.0, scenes::kMaxWindSpeed));
  cmd->add_option("--quality", args.quality, "Leaf quality factor (0, 1]")
      ->check(CLI::Range(0.001, 1.0));
  cmd->add_option("--age", args.age, "The tree at this age, years (docs/SPECIES.md \"Age\")")
      ->check(CLI::Range(0.0, 500.0));
  cmd->add_option("--obj", args.obj, "Write the full-detail mesh as Wavefront OBJ");
  cmd->add_option("--internodes", args.internodes,
                  "Self-organising species: write every internode (index, parent, step, ...) "
                  "as CSV, the indices [[prune]] and [[width_constraint]] name");
  cmd->add_flag("--json", args.json, "Print one JSON object on stdout");
  return cmd;
}

namespace {

// The self-organising plant the tree was drawn from, one internode per row: what a pruning or
// a width constraint names by index (TreeSketch's taps, written down).
void write_internodes(const trees::Species& species, const TreeArgs& args) {
  const auto* p = std::get_if<trees::self_organizing::Parameters>(&species.parameters);
  if (p == nullptr)
    throw InputError(args.species +
                     ": --internodes: only self-organising species have "
                     "internodes (this one is " +
                     trees::core_name(species) + ")");
  trees::self_organizing::Parameters grown = *p;
  grown.steps = trees::self_organizing_steps(species, args.age);
  const trees::self_organizing::Plant plant = trees::self_organizing::grow(grown, args.seed);
  AtomicFile file(args.internodes);
  {
    std::ofstream out(file.temp_path());
    out << "internode,parent,step,order,rank,alive,stub,starts_branch,base_x,base_y,base_z,tip_x,"
           "tip_y,tip_z,width\n";
    for (std::uint32_t i = 0; i < plant.size(); ++i) {
      const trees::self_organizing::Internode& n = plant[i];
      out << fmt::format(
          "{},{},{},{},{},{},{},{},{:.4f},{:.4f},{:.4f},{:.4f},{:.4f},{:.4f},{:.5f}\n", i,
          n.parent == trees::self_organizing::kNone ? std::string() : std::to_string(n.parent),
          n.birth, n.order, n.rank, n.alive ? 1 : 0, n.stub ? 1 : 0, plant.starts_branch(i) ? 1 : 0,
          n.base.x, n.base.y, n.base.z, n.tip.x, n.tip.y, n.tip.z, n.width);
    }
  }
  file.commit();
}

}  // namespace

int run_tree(const TreeArgs& args) {
  // One tree is a few large arrays built and freed in turn. glibc's defaults hand every freed
  // array of 128 kB or more back to the system and fault the next one in page by page, which
  // on a virtual machine costs a tenth of the command (docs/PERFORMANCE.md "Start-up"); a
  // short-lived process keeps its memory instead.
  mallopt(M_MMAP_THRESHOLD, 256 << 20);
  mallopt(M_TRIM_THRESHOLD, 1 << 30);
  const trees::Species species = trees::load_species(args.species);
  const auto start = std::chrono::steady_clock::now();
  const trees::Tree tree = trees::generate(
      species, {args.seed, args.time, args.wind, args.gust, args.quality, args.age});
  const double ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  if (!args.obj.empty()) exporters::write_obj(tree.geometry, args.obj);
  if (!args.internodes.empty()) write_internodes(species, args);

  const trees::TreeStats& s = tree.stats;
  int total = 0;
  for (int n : s.stems_per_level) total += n;
  if (args.json) {
    const nlohmann::json out = {
        {"species", species.name},
        {"core", trees::core_name(species)},
        {"seed", args.seed},
        {"stems", {{"total", total}, {"per_level", s.stems_per_level}, {"clones", s.clones}}},
        {"leaves", s.leaves},
        {"triangles", tree.geometry.triangle_count()},
        {"height_m", s.height},
        {"crown_radius_m", s.crown_radius},
        {"generate_ms", ms}};
    std::cout << out.dump() << "\n";
    return 0;
  }
  std::string levels;
  for (int n : s.stems_per_level) levels += (levels.empty() ? "" : " + ") + std::to_string(n);
  std::cout << fmt::format("{} ({}), seed {}\n", species.name, trees::core_name(species), args.seed)
            << fmt::format("  stems     {} = {} ({} clones)\n", total, levels, s.clones)
            << fmt::format("  leaves    {}\n", s.leaves)
            << fmt::format("  triangles {}\n", tree.geometry.triangle_count())
            << fmt::format("  height    {:.2f} m, crown radius {:.2f} m\n", s.height,
                           s.crown_radius)
            << fmt::format("  generated in {:.1f} ms\n", ms);
  return 0;
}

}  // namespace landsim::app
