#include "plate_command.h"

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include "scenes/contact_sheet.h"
#include "trees/degradation.h"
#include "trees/species.h"

namespace landsim::app {

CLI::App* add_plate_command(CLI::App& app, PlateArgs& args) {
  CLI::App* cmd = app.add_subcommand(
      "plate", "Render Weber & Penn's Plate 4: one tree degraded for each range, side by side");
  cmd->add_option("species", args.species, "Species file (.toml, or Arbaro .xml)")->required();
  cmd->add_option("--out", args.out, "PNG file to write")->required();
  cmd->add_option("--ranges", args.ranges, "Ranges in metres (the paper's calibration)")
      ->delimiter(',')
      ->check(CLI::Range(0.0, 1e7));
  cmd->add_option("--season", args.season, "spring, summer, autumn or winter")
      ->check(CLI::IsMember({"spring", "summer", "autumn", "winter"}));
  cmd->add_option("--quality", args.quality, "The paper's quality factor (0, 1]")
      ->check(CLI::Range(0.001, 1.0));
  cmd->add_flag("--evergreen", args.evergreen, "The tree keeps its leaves (s = quality / 2)");
  cmd->add_option("--seed", args.seed, "Variant seed")->capture_default_str();
  cmd->add_option("--tile", args.tile, "Panel size, pixels")->check(CLI::Range(32, 2048));
  cmd->add_option("--spp", args.spp, "Samples per pixel")->check(CLI::Range(1, 4096));
  return cmd;
}

int run_plate(const PlateArgs& args) {
  const trees::Species species = trees::load_species(args.species);
  trees::TreeOptions options;
  options.seed = args.seed;
  options.quality = args.quality;
  const trees::TreeGeometry tree = trees::generate(species, options).geometry;
  scenes::ContactSheetOptions o;
  o.tile = args.tile;
  o.spp = args.spp;
  o.seed = args.seed;
  o.factors = trees::degradation_factors(args.quality, *trees::season_from_name(args.season),
                                         args.evergreen);
  const renderer::Film plate = scenes::render_plate(tree, args.ranges, o);
  std::vector<std::string> labels;
  for (double r : args.ranges) labels.push_back(fmt::format("{:g} m", r));
  o.columns = static_cast<int>(args.ranges.size());
  scenes::write_labelled_png(plate, labels, o, args.out);
  return 0;
}

}  // namespace landsim::app
