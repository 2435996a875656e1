#include "degraded_tree.h"

#include <CLI/CLI.hpp>

#include "trees/species.h"

namespace landsim::app {

void add_degraded_tree_options(CLI::App& cmd, DegradedTreeArgs& args) {
  cmd.add_option("species", args.species, "Species file (.toml, or Arbaro .xml)")->required();
  cmd.add_option("--ranges", args.ranges, "Ranges in metres")
      ->delimiter(',')
      ->check(CLI::Range(0.0, 1e7));
  cmd.add_option("--season", args.season, "spring, summer, autumn or winter")
      ->check(CLI::IsMember({"spring", "summer", "autumn", "winter"}));
  cmd.add_option("--quality", args.quality, "The paper's quality factor (0, 1]")
      ->check(CLI::Range(0.001, 1.0));
  cmd.add_flag("--evergreen", args.evergreen, "The tree keeps its leaves (s = quality / 2)");
  cmd.add_option("--seed", args.seed, "Variant seed")->capture_default_str();
}

DegradedTree load_degraded_tree(const DegradedTreeArgs& args) {
  const trees::Species species = trees::load_species(args.species);
  trees::TreeOptions options;
  options.seed = args.seed;
  options.quality = args.quality;
  DegradedTree t{species.name, trees::generate(species, options).geometry, {}};
  const trees::Season season = *trees::season_from_name(args.season);
  if (season == trees::Season::winter && !args.evergreen)
    t.geometry.group(trees::Group::leaves) = trees::GroupGeometry{};
  t.factors = trees::degradation_factors(args.quality, season, args.evergreen);
  return t;
}

}  // namespace landsim::app
