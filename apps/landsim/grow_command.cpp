#include "grow_command.h"

#include <fmt/format.h>
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>

#include "core/atomic_file.h"
#include "core/input_error.h"
#include "exporters/contact_sheet.h"
#include "renderer/image_output.h"
#include "renderer/render.h"
#include "scenario_input.h"
#include "scenes/scenario.h"
#include "trees/measured_growth/dimensions.h"
#include "trees/measured_growth/generator.h"
#include "trees/species.h"

namespace landsim::app {

CLI::App* add_grow_command(CLI::App& app, GrowArgs& args) {
  CLI::App* cmd = app.add_subcommand(
      "grow", "Grow a measured-growth species through several ages: images and a growth table");
  cmd->add_option("species", args.species, "Species file (core = \"measured_growth\")")->required();
  cmd->add_option("--ages", args.ages, "Ages in years, comma-separated")
      ->delimiter(',')
      ->check(CLI::Range(0.0, 500.0))
      ->capture_default_str();
  cmd->add_option("--out", args.out, "Output directory")->required();
  cmd->add_option("--seed", args.seed, "Variant seed")->capture_default_str();
  cmd->add_option("--width", args.width, "Image width")->check(CLI::Range(16, 8192));
  cmd->add_option("--height", args.height, "Image height")->check(CLI::Range(16, 8192));
  add_spp_option(*cmd, args.spp);
  cmd->add_flag("--json", args.json, "Print growth.json on stdout too");
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

// The tree and, beside it, the figure; the camera the same for every age: framing the oldest.
renderer::Scene growth_scene(const trees::Tree& tree, const trees::Species& species,
                             double frame_size, const GrowArgs& args, renderer::View& view) {
  renderer::Scene s = exporters::studio_scene(static_cast<float>(20.0 * frame_size));
  renderer::TreePrototype t;
  t.geometry = tree.geometry;
  t.bark_albedo = species.colours.bark;
  t.leaf_reflectance = species.colours.leaf;
  t.leaf_transmittance = species.colours.leaf * 0.5f;
  renderer::TreePrototype person;
  person.geometry = exporters::person_figure();
  person.bark_albedo = {0.35f, 0.12f, 0.10f};
  s.prototypes = {t, person};
  s.instances = {{0, {0, 0, 0}, 0.0, 1.0}, {1, {0.4 * frame_size, -2.0, 0}, 0.0, 1.0}};
  s.settings.spp = args.spp;
  s.settings.seed = args.seed;
  const Vec3 centre{0.1 * frame_size, 0, 0.5 * frame_size};
  view = {"growth",   centre + normalize(Vec3{-0.3, -1.0, 0.1}) * (2.3 * frame_size),
          centre,     40.0,
          args.width, args.height};

  return s;
}

}  // namespace

int run_grow(const GrowArgs& args) {
  const trees::Species species = trees::load_species(args.species);
  if (!trees::uses_core<trees::measured_growth::Parameters>(species))
    throw InputError(args.species +
                     ": core: `landsim grow` needs a measured-growth species "
                     "(core = \"measured_growth\"), got " +
                     trees::core_name(species));
  scenes::check_image_size(args.width, args.height, "--width/--height");
  const auto& p = std::get<trees::measured_growth::Parameters>(species.parameters);
  const std::filesystem::path out(args.out);
  std::filesystem::create_directories(out);
  const double oldest = *std::max_element(args.ages.begin(), args.ages.end());
  const auto& a = p.allometry;
  const double frame_size = std::max(a.f_height(std::min(oldest, a.max_age)), 1.0);
  nlohmann::json rows = nlohmann::json::array();
  for (double requested : args.ages) {
    const double age = trees::measured_growth::clamp_age(p, requested);
    const trees::Tree tree = trees::generate(species, {.seed = args.seed, .age = age});
    renderer::View view;
    const renderer::Scene scene = growth_scene(tree, species, frame_size, args, view);
    const renderer::Film film = renderer::Renderer(scene).render(view, {});
    const std::string stem = fmt::format("age_{:03d}", static_cast<int>(std::lround(requested)));
    renderer::write_exr(film, out / (stem + ".exr"),
                        {{"species", species.name}, {"age_years", fmt::format("{}", age)}});
    renderer::write_preview_png(film, out / (stem + ".png"), std::nullopt);
    rows.push_back({{"age", requested},
                    {"age_used", age},
                    {"image", stem + ".png"},
                    {"model", dimensions_json(trees::measured_growth::measure(tree.geometry))},
                    {"equations", equations_json(a, age)}});
  }
  const nlohmann::json table = {{"species", species.name}, {"seed", args.seed}, {"ages", rows}};
  AtomicFile file(out / "growth.json");
  std::ofstream(file.temp_path()) << table.dump(2) << "\n";
  file.commit();
  if (args.json)
    std::cout << table.dump() << "\n";
  else
    std::cout << fmt::format("{}: {} ages, growth.json written\n", out.string(), rows.size());
  return 0;
}

}  // namespace landsim::app
