#include "plate_command.h"

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include "exporters/contact_sheet.h"
#include "scenario_input.h"

namespace landsim::app {

CLI::App* add_plate_command(CLI::App& app, PlateArgs& args) {
  CLI::App* cmd = app.add_subcommand(
      "plate", "Render Weber & Penn's Plate 4: one tree degraded for each range, side by side");
  add_degraded_tree_options(*cmd, args.tree);
  cmd->add_option("--out", args.out, "PNG file to write")->required();
  cmd->add_option("--tile", args.tile, "Panel size, pixels")->check(CLI::Range(32, 2048));
  add_spp_option(*cmd, args.spp);
  return cmd;
}

int run_plate(const PlateArgs& args) {
  const DegradedTree tree = load_degraded_tree(args.tree);
  exporters::ContactSheetOptions o;
  o.tile = args.tile;
  o.spp = args.spp;
  o.seed = args.tree.seed;
  o.factors = tree.factors;
  const renderer::Film plate = exporters::render_plate(tree.geometry, args.tree.ranges, o);
  std::vector<std::string> labels;
  for (double r : args.tree.ranges) labels.push_back(fmt::format("{:g} m", r));
  o.columns = static_cast<int>(args.tree.ranges.size());
  exporters::write_labelled_png(plate, labels, o, args.out);
  return 0;
}

}  // namespace landsim::app
