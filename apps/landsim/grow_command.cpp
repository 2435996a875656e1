#include "grow_command.h"

#include <fmt/format.h>
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <numbers>

#include "core/atomic_file.h"
#include "core/input_error.h"
#include "exporters/contact_sheet.h"
#include "renderer/output/image_output.h"
#include "renderer/transport/render.h"
#include "scenario_input.h"
#include "scenes/scenario/scenario.h"
#include "trees/measured_growth/dimensions.h"
#include "trees/measured_growth/generator.h"
#include "trees/species.h"

namespace landsim::app {

CLI::App* add_grow_command(CLI::App& app, GrowArgs& args) {
  CLI::App* cmd = app.add_subcommand(
      "grow", "One tree of a species through several ages: images and a growth table");
  cmd->add_option("species", args.species, "Species file (any core)")->required();
  cmd->add_option("--ages", args.ages,
                  "Ages in years, comma-separated (default: 10,20,30,40,50 for measured "
                  "growth, a fifth to all of the species' mature age otherwise)")
      ->delimiter(',')
      ->check(CLI::Range(0.0, 500.0));
  cmd->add_option("--out", args.out, "Output directory")->required();
  cmd->add_option("--seed", args.seed, "Variant seed")->capture_default_str();
  cmd->add_option("--width", args.width, "Image width")->check(CLI::Range(16, 8192));
  cmd->add_option("--height", args.height, "Image height")->check(CLI::Range(16, 8192));
  add_spp_option(*cmd, args.spp);
  cmd->add_flag("--json", args.json, "Print growth.json on stdout too");
  cmd->add_flag("--cutaway", args.cutaway,
                "Ground only behind the trees, framed down to the deepest root: root systems "
                "show as in a cross-section");
  return cmd;
}

namespace {

nlohmann::json dimensions_json(const trees::measured_growth::Dimensions& d) {
  return {{"height_m", d.height_m},
          {"crown_diameter_m", d.crown_diameter_m},
          {"crown_height_m", d.crown_height_m},
          {"dbh_cm", d.dbh_cm},
          {"leaf_area_m2", d.leaf_area_m2}};
}

nlohmann::json equations_json(const trees::measured_growth::Allometry& a, double age) {
  return {{"height_m", a.f_height(age)},
          {"crown_diameter_m", a.f_crown_diameter(age)},
          {"crown_height_m", a.f_crown_height(age)},
          {"dbh_cm", a.f_dbh(age)},
          {"leaf_area_m2", a.f_leaf_area(age)}};
}

// The tree as a prototype with the species' colours.
renderer::TreePrototype prototype(const trees::Tree& tree, const trees::Species& species) {
  renderer::TreePrototype t;
  t.geometry = tree.geometry;
  t.dress(species.colours);
  return t;
}

// How far below the ground the deepest tree reaches (its roots), metres; 0 unless cutaway.
double depth_shown(const std::vector<trees::Tree>& trees, const GrowArgs& args) {
  double depth = 0.0;
  if (args.cutaway)
    for (const trees::Tree& t : trees)
      depth = std::max(depth, -static_cast<double>(t.geometry.bounds()[0].z));
  return depth;
}

// Where the figure stands: in front of the trees, or behind the cut on the ground that is left.
double figure_y(const GrowArgs& args, double in_front) { return args.cutaway ? 1.0 : in_front; }

// The tree and, beside it, the figure; the camera the same for every age: framing the oldest
// (in a cutaway, from the deepest root up, the camera level with the ground).
renderer::Scene growth_scene(const trees::Tree& tree, const trees::Species& species,
                             double frame_size, double depth, const GrowArgs& args,
                             renderer::View& view) {
  renderer::Scene s = exporters::studio_scene(static_cast<float>(20.0 * frame_size), args.cutaway);
  s.prototypes = {prototype(tree, species), exporters::person_figure()};
  s.instances = {{0, {0, 0, 0}, 0.0, 1.0},
                 {1, {0.4 * frame_size, figure_y(args, -2.0), 0}, 0.0, 1.0}};
  s.settings.spp = args.spp;
  s.settings.seed = args.seed;
  frame_size += depth;
  const Vec3 centre{0.1 * frame_size, 0, 0.5 * frame_size - depth};
  Vec3 from = centre + normalize(Vec3{-0.3, -1.0, 0.1}) * (2.3 * frame_size);
  if (args.cutaway) from.z = 0.0;  // the cut seen edge-on: the tree above it, roots below
  view = {"growth", from, centre, 40.0, args.width, args.height};

  return s;
}

// growth.png: every age side by side, youngest on the left (the measured-growth paper's
// figure of ages 10 to 50), seen from the south under one camera, the person beside the
// youngest, each age written above its tree.
void write_growth_figure(const std::vector<trees::Tree>& trees, const trees::Species& species,
                         const std::vector<double>& ages, const GrowArgs& args,
                         const std::filesystem::path& path) {
  double height = 1.0, crown = 1.0;
  for (const trees::Tree& t : trees) {
    height = std::max(height, t.stats.height);
    crown = std::max(crown, 2.0 * t.stats.crown_radius);
  }
  const double depth = depth_shown(trees, args);
  height += depth;
  const double spacing = 1.15 * std::max(crown, 0.5 * height);
  const auto n = static_cast<double>(trees.size());
  renderer::Scene s =
      exporters::studio_scene(static_cast<float>(20.0 * (n * spacing + height)), args.cutaway);
  s.prototypes = {exporters::person_figure()};
  const auto x_of = [&](std::size_t i) {
    return (static_cast<double>(i) - 0.5 * (n - 1)) * spacing;
  };
  s.instances = {{0, {x_of(0) - 0.4 * spacing, figure_y(args, -1.0), 0}, 0.0, 1.0}};
  for (std::size_t i = 0; i < trees.size(); ++i) {
    s.prototypes.push_back(prototype(trees[i], species));
    s.instances.push_back({static_cast<std::uint32_t>(i + 1), {x_of(i), 0, 0}, 0.0, 1.0});
  }
  s.settings.spp = args.spp;
  s.settings.seed = args.seed;
  // Framing: the row's width (and a margin) across, the tallest tree (and room for the
  // labels) up; the camera on the horizontal through mid-height.
  const int h_px = args.height;
  const int w_px = std::clamp(static_cast<int>(std::lround(h_px * 0.75 * n)), h_px, 8192);
  const double half_y = std::tan(15.0 * std::numbers::pi / 180.0);
  const double half_x = half_y * w_px / h_px;
  const double d = std::max(0.55 * (n * spacing) / half_x, 0.65 * height / half_y);
  const Vec3 centre{0, 0, 0.5 * height - depth};
  // In a cutaway the camera is level with the ground, looking up at the middle.
  const Vec3 from = centre + Vec3{0, -d, args.cutaway ? -centre.z : 0.0};
  const renderer::View view{"growth", from, centre, 30.0, w_px, h_px};
  const renderer::Film film = renderer::Renderer(s).render(view, {});
  std::vector<renderer::ImageLabel> labels;
  for (std::size_t i = 0; i < trees.size(); ++i) {
    const double x = 0.5 * w_px * (1.0 + x_of(i) / (d * half_x));
    labels.push_back({static_cast<int>(x) - 24, 16, fmt::format("{:g} years", ages[i])});
  }
  renderer::write_preview_png(film, path, std::nullopt, labels);
}

}  // namespace

namespace {

// The ages asked for, or the core's defaults.
std::vector<double> ages_to_grow(const GrowArgs& args, const trees::Species& species) {
  if (!args.ages.empty()) return args.ages;
  if (trees::uses_core<trees::measured_growth::Parameters>(species)) return {10, 20, 30, 40, 50};
  std::vector<double> ages;
  for (int k = 1; k <= 5; ++k)
    ages.push_back(species.age.mature >= 5.0  // whole years, unless it matures within five
                       ? std::round(species.age.mature * k / 5.0)
                       : std::round(species.age.mature * k / 5.0 * 10.0) / 10.0);
  return ages;
}

// The age a core draws for `requested` (its data's range, or 1 year to the mature age).
double age_used(const trees::Species& species, double requested) {
  if (const auto* p = std::get_if<trees::measured_growth::Parameters>(&species.parameters))
    return std::clamp(requested, 0.0, p->allometry.max_age);  // generate warns
  return trees::clamped_age(species.age, requested);
}

std::size_t stem_count(const trees::Tree& tree) {
  std::size_t n = 0;
  for (int k : tree.stats.stems_per_level) n += static_cast<std::size_t>(k);
  return n;
}

}  // namespace

int run_grow(const GrowArgs& args) {
  const trees::Species species = trees::load_species(args.species);
  scenes::check_image_size(args.width, args.height, "--width/--height");
  const std::vector<double> ages = ages_to_grow(args, species);
  const auto* measured = std::get_if<trees::measured_growth::Parameters>(&species.parameters);
  const std::filesystem::path out(args.out);
  std::filesystem::create_directories(out);
  std::vector<trees::Tree> trees = trees::generate_ages(species, {.seed = args.seed}, ages);
  // One camera for every age, framing the tallest.
  double frame_size = 1.0;
  for (const trees::Tree& t : trees) frame_size = std::max(frame_size, t.stats.height);
  const double depth = depth_shown(trees, args);
  nlohmann::json rows = nlohmann::json::array();
  for (std::size_t i = 0; i < ages.size(); ++i) {
    const double requested = ages[i], age = age_used(species, requested);
    const trees::Tree& tree = trees[i];
    renderer::View view;
    const renderer::Scene scene = growth_scene(tree, species, frame_size, depth, args, view);
    const renderer::Film film = renderer::Renderer(scene).render(view, {});
    const std::string stem = fmt::format("age_{:03d}", static_cast<int>(std::lround(requested)));
    renderer::write_exr(film, out / (stem + ".exr"),
                        {{"species", species.name}, {"age_years", fmt::format("{}", age)}});
    renderer::write_preview_png(film, out / (stem + ".png"), std::nullopt,
                                {{6, 16, fmt::format("{:g} years, {}", age, species.name)}});
    nlohmann::json row = {
        {"age", requested},
        {"age_used", age},
        {"image", stem + ".png"},
        {"model", dimensions_json(trees::measured_growth::measure(tree.geometry))},
        {"stems", stem_count(tree)},
        {"leaves", tree.stats.leaves}};
    if (measured != nullptr) {
      // The equations' mean tree, and this tree's own sizes (its draw from their scatter).
      row["equations"] = equations_json(measured->allometry, age);
      row["individual"] = equations_json(
          trees::measured_growth::individual(measured->allometry, args.seed, measured->scatter),
          age);
    }
    rows.push_back(row);
  }
  std::vector<double> used;
  for (double a : ages) used.push_back(age_used(species, a));
  write_growth_figure(trees, species, used, args, out / "growth.png");
  const nlohmann::json table = {{"species", species.name},
                                {"core", trees::core_name(species)},
                                {"seed", args.seed},
                                {"ages", rows}};
  write_file_atomically(out / "growth.json", table.dump(2) + "\n");
  if (args.json)
    std::cout << table.dump() << "\n";
  else
    std::cout << fmt::format("{}: {} ages, growth.json written\n", out.string(), rows.size());
  return 0;
}

}  // namespace landsim::app
