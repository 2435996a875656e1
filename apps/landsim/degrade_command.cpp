#include "degrade_command.h"

#include <fmt/format.h>
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <iostream>

#include "trees/degradation.h"

namespace landsim::app {
namespace {

// One row of Table 2; level 2 holds level 3+ too, as the paper groups them.
struct Row {
  double range = 0.0, r2 = 0.0;
  std::uint32_t trunk_triangles = 0, trunk_lines = 0, level1_triangles = 0, level1_lines = 0,
                level2_triangles = 0, level2_lines = 0, leaf_triangles = 0, leaf_points = 0;
};

Row table_row(const trees::TreeGeometry& tree, double range, double r2,
              const trees::DegradationFactors& f) {
  const trees::TreeDetail d = trees::tree_detail(tree, r2, f);
  const auto& g = d.groups;
  const auto l = [](trees::Group group) { return static_cast<std::size_t>(group); };
  Row row{range, r2};
  row.trunk_triangles = g[l(trees::Group::trunk)].triangles;
  row.trunk_lines = g[l(trees::Group::trunk)].far_primitives;
  row.level1_triangles = g[l(trees::Group::level1)].triangles;
  row.level1_lines = g[l(trees::Group::level1)].far_primitives;
  row.level2_triangles =
      g[l(trees::Group::level2)].triangles + g[l(trees::Group::level3plus)].triangles;
  row.level2_lines =
      g[l(trees::Group::level2)].far_primitives + g[l(trees::Group::level3plus)].far_primitives;
  row.leaf_triangles = g[l(trees::Group::leaves)].triangles;
  row.leaf_points = g[l(trees::Group::leaves)].far_primitives;
  return row;
}

void print_json(const std::string& species, const std::vector<Row>& rows) {
  nlohmann::json out = {{"species", species}, {"rows", nlohmann::json::array()}};
  for (const Row& r : rows)
    out["rows"].push_back({{"range_m", r.range},
                           {"r2", r.r2},
                           {"trunk_triangles", r.trunk_triangles},
                           {"trunk_lines", r.trunk_lines},
                           {"level1_triangles", r.level1_triangles},
                           {"level1_lines", r.level1_lines},
                           {"level2_triangles", r.level2_triangles},
                           {"level2_lines", r.level2_lines},
                           {"leaf_triangles", r.leaf_triangles},
                           {"leaf_points", r.leaf_points}});
  std::cout << out.dump() << "\n";
}

// The paper's layout: one line per item and primitive, one column per range.
void print_table(const std::string& species, const std::vector<Row>& rows, const DegradeArgs& a) {
  std::cout << fmt::format("{}: elements drawn at each range ({}, quality {}, {} px, {} deg)\n",
                           species, a.tree.season, a.tree.quality, a.height, a.fov);
  const auto line = [&](const char* name, auto field) {
    std::cout << fmt::format("{:<18}", name);
    for (const Row& r : rows) std::cout << fmt::format("{:>9}", field(r));
    std::cout << "\n";
  };
  line("Range (m)", [](const Row& r) { return fmt::format("{:g}", r.range); });
  line("r2", [](const Row& r) { return fmt::format("{:.0f}", r.r2); });
  line("Level 0 Triangles", [](const Row& r) { return r.trunk_triangles; });
  line("Level 0 Lines", [](const Row& r) { return r.trunk_lines; });
  line("Level 1 Triangles", [](const Row& r) { return r.level1_triangles; });
  line("Level 1 Lines", [](const Row& r) { return r.level1_lines; });
  line("Level 2 Triangles", [](const Row& r) { return r.level2_triangles; });
  line("Level 2 Lines", [](const Row& r) { return r.level2_lines; });
  line("Leaf Triangles", [](const Row& r) { return r.leaf_triangles; });
  line("Leaf Points", [](const Row& r) { return r.leaf_points; });
}

}  // namespace

CLI::App* add_degrade_command(CLI::App& app, DegradeArgs& args) {
  CLI::App* cmd =
      app.add_subcommand("degrade", "Print Weber & Penn's Table 2 (range degradation) for a tree");
  add_degraded_tree_options(*cmd, args.tree);
  cmd->add_option("--height", args.height, "Image height, pixels")->check(CLI::Range(1, 65536));
  cmd->add_option("--fov", args.fov, "Vertical field of view, degrees")
      ->check(CLI::Range(0.01, 179.0));
  cmd->add_flag("--paper", args.paper,
                "The paper's calibration (1000 pixels, 60 degrees: r2 = range)");
  cmd->add_flag("--json", args.json, "Print one JSON object on stdout");
  return cmd;
}

int run_degrade(const DegradeArgs& args) {
  const DegradedTree tree = load_degraded_tree(args.tree);
  const int height = args.paper ? 1000 : args.height;
  const double fov = args.paper ? 60.0 : args.fov;
  std::vector<Row> rows;
  for (double range : args.tree.ranges)
    rows.push_back(
        table_row(tree.geometry, range, trees::calibrated_range(range, height, fov), tree.factors));
  if (args.json) {
    print_json(tree.name, rows);
  } else {
    DegradeArgs shown = args;
    shown.height = height;
    shown.fov = fov;
    print_table(tree.name, rows, shown);
  }
  return 0;
}

}  // namespace landsim::app
