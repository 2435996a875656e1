#include "scenes/scenario/detail/vegetation_reader.h"

#include <fmt/format.h>

#include <set>

#include "featuremaps/placement.h"
#include "params/table_reader.h"
#include "scenes/scenario/detail/relative_path.h"
#include "scenes/scenario/detail/toml_tables.h"
#include "terrain/raster_files.h"
#include "trees/species.h"

namespace landsim::scenes::detail {

namespace {

using params::Range;
using params::TableReader;

}  // namespace

std::optional<FeatureMapSettings> read_featuremaps(const toml::table& root, const std::string& file,
                                                   const std::string& base_dir) {
  if (!root.contains("featuremaps")) return std::nullopt;
  TableReader r(sub_table(root, "featuremaps", file, true), "featuremaps", file);
  FeatureMapSettings f;
  // An optional path key: resolved against the scenario, checked to exist.
  const auto path = [&](std::string_view key) -> std::string {
    r.allow(key);
    if (!r.has(key)) return {};
    const std::string p = resolve(base_dir, r.string(key));
    if (!terrain::raster_file_exists(p)) r.fail(key, "file not found: " + p);
    return p;
  };
  f.vegetation = path("vegetation");
  f.classes = path("classes");
  f.class_map = path("class_map");
  f.soil = path("soil");
  f.rock = path("rock");
  f.water = path("water");
  f.road = path("road");
  f.placement.cell_size = r.optional_number("cell_size", kPositive);
  if (const auto o = r.optional_numbers("origin", 2, Range{-1e12, 1e12})) {
    f.placement.origin = std::array<double, 2>{(*o)[0], (*o)[1]};
  }
  if (!f.vegetation.empty() && !f.classes.empty()) {
    r.fail("vegetation",
           "give either vegetation (a 16-bit map) or classes with class_map, not both");
  }
  if (!f.classes.empty() && f.class_map.empty()) r.fail("class_map", "required with classes");
  r.finish();
  return f;
}

namespace {

// The optional `age` of a [[species]] table: years, or [youngest, oldest] across variants
// (every core; trees/tree_age.h, docs/SPECIES.md "Age").
void read_age(TableReader& r, const toml::table& t, SpeciesSettings& s) {
  r.allow("age");
  const toml::node* n = t.get("age");
  if (n == nullptr) return;
  const auto years = [&](const toml::node& v) {
    const auto x = v.value<double>();
    if (!x || !(*x >= 0.0 && *x <= 500.0))
      r.fail("age", "expected years from 0 to 500, or [youngest, oldest]");
    return *x;
  };
  if (const toml::array* range = n->as_array()) {
    if (range->size() != 2) r.fail("age", "expected [youngest, oldest]");
    s.age_min = years(*range->get(0));
    s.age_max = years(*range->get(1));
    if (s.age_max < s.age_min) r.fail("age", "expected [youngest, oldest] with youngest first");
  } else {
    s.age_min = s.age_max = years(*n);
  }
}

// cover = "everywhere" | a fraction in (0, 1] | { rectangle = [x0, y0, x1, y1] } |
// { polygon = [[x, y], ...] }, terrain coordinates.
featuremaps::Cover read_cover(TableReader& r) {
  constexpr const char* kExpected =
      "expected \"everywhere\", a fraction of the terrain in (0, 1], { rectangle = [west, "
      "south, east, north] } or { polygon = [[x, y], ...] } in terrain coordinates";
  const toml::node* n = r.value("cover", kExpected);
  featuremaps::Cover c;
  if (const auto* s = n->as_string()) {
    if (s->get() != "everywhere")
      r.fail_at(*n, "cover", std::string(kExpected) + ", got \"" + s->get() + "\"");
    return c;
  }
  if (n->is_number()) {
    c.kind = featuremaps::Cover::Kind::fraction;
    c.fraction = n->value<double>().value_or(0.0);
    if (!(c.fraction > 0.0 && c.fraction <= 1.0))
      r.fail_at(*n, "cover", fmt::format("{}, got {}", kExpected, c.fraction));
    return c;
  }
  const toml::table* t = n->as_table();
  if (t == nullptr || t->size() != 1 || !(t->contains("rectangle") || t->contains("polygon")))
    r.fail_at(*n, "cover", kExpected);
  c.kind = featuremaps::Cover::Kind::polygon;
  const toml::array* a = t->get_as<toml::array>(t->contains("rectangle") ? "rectangle" : "polygon");
  const auto number = [&](const toml::node* v) {
    if (v == nullptr || !v->is_number()) r.fail_at(*n, "cover", kExpected);
    return v->value<double>().value_or(0.0);
  };
  if (a == nullptr) r.fail_at(*n, "cover", kExpected);
  if (t->contains("rectangle")) {
    if (a->size() != 4) r.fail_at(*n, "cover", "rectangle: expected [west, south, east, north]");
    const double w = number(a->get(0)), s = number(a->get(1)), e = number(a->get(2)),
                 no = number(a->get(3));
    if (!(e > w && no > s))
      r.fail_at(*n, "cover", "rectangle: expected east > west and north > south");
    c.polygon = {{w, s}, {e, s}, {e, no}, {w, no}};
    return c;
  }
  for (const toml::node& v : *a) {
    const toml::array* p = v.as_array();
    if (p == nullptr || p->size() != 2) r.fail_at(*n, "cover", "polygon: expected [[x, y], ...]");
    c.polygon.push_back({number(p->get(0)), number(p->get(1))});
  }
  if (c.polygon.size() < 3) r.fail_at(*n, "cover", "polygon: expected at least 3 corners");
  return c;
}

// Fraction covers share the terrain out: together at most all of it.
template <typename Settings>
void check_fractions(const std::vector<Settings>& items, const toml::array& tables,
                     const std::string& name, const std::string& file) {
  double total = 0.0;
  for (std::size_t i = 0; i < items.size(); ++i) {
    if (!items[i].cover || items[i].cover->kind != featuremaps::Cover::Kind::fraction) continue;
    total += items[i].cover->fraction;
    if (total > 1.0 + 1e-9) {
      TableReader r(*tables.get(i)->as_table(), name + "[" + std::to_string(i) + "]", file);
      r.fail("cover", fmt::format("the fractions of the [[{}]] covers add up to {:.3g}; "
                                  "expected at most 1 (they share the terrain out)",
                                  name, total));
    }
  }
}

}  // namespace

std::vector<SpeciesSettings> read_species(const toml::table& root, const std::string& file,
                                          const std::string& base_dir) {
  std::vector<SpeciesSettings> out;
  const toml::array* a = tables(root, "species", file);
  if (a == nullptr) return out;
  std::set<int> bits;
  for (std::size_t i = 0; i < a->size(); ++i) {
    TableReader r(*a->get(i)->as_table(), "species[" + std::to_string(i) + "]", file);
    SpeciesSettings s;
    s.location = r.location(nullptr);
    s.bit = static_cast<int>(r.integer("bit", 0, featuremaps::kTreeBits - 1));
    if (!bits.insert(s.bit).second)
      r.fail("bit", "species bit " + std::to_string(s.bit) + " is used twice");
    const std::string species_file = resolve(base_dir, r.string("file"));
    const std::optional<std::string> text = terrain::read_text_file(species_file);
    if (!text) r.fail("file", "species file not found: " + species_file);
    s.species = trees::parse_species(*text, species_file);
    if (r.has("leaf_optics")) {
      TableReader optics = r.table("leaf_optics");
      s.species.colours.leaf_optics = trees::read_leaf_contents(optics);
    }
    s.variants = static_cast<int>(r.integer("variants", 1, 256, s.variants));
    s.density_per_ha = r.number("density_per_ha", Range{0.0, 100000.0, true}, s.density_per_ha);
    s.scale_variation = r.number("scale_variation", Range{0.0, 0.9}, s.scale_variation);
    s.colour_variation = r.number("colour_variation", Range{0.0, 0.9}, s.colour_variation);
    s.min_spacing = r.number("min_spacing", Range{0.0, 1000.0}, s.min_spacing);
    // Trees stand on a jittered grid of one tree per spacing^2 (featuremaps/placement.h).
    if (const double grid = featuremaps::grid_spacing(s.density_per_ha); s.min_spacing > grid)
      r.fail("min_spacing", fmt::format("expected at most the grid spacing {:.3g} m of "
                                        "density_per_ha {} (one tree per {:.3g} m square), got {}",
                                        grid, s.density_per_ha, grid, s.min_spacing));
    if (r.has("bark_texture")) {
      s.bark_texture = resolve(base_dir, r.string("bark_texture"));
      if (!terrain::raster_file_exists(s.bark_texture))
        r.fail("bark_texture", "file not found: " + s.bark_texture);
    }
    r.allow("bark_texture");
    read_age(r, *a->get(i)->as_table(), s);
    s.evergreen = r.boolean("evergreen", s.evergreen);
    if (r.has("cover")) s.cover = read_cover(r);
    r.finish();
    out.push_back(std::move(s));
  }
  check_fractions(out, *a, "species", file);
  return out;
}

std::vector<GrassSettings> read_grass(const toml::table& root, const std::string& file) {
  std::vector<GrassSettings> out;
  const toml::array* a = tables(root, "grass", file);
  if (a == nullptr) return out;
  std::set<int> types;
  for (std::size_t i = 0; i < a->size(); ++i) {
    TableReader r(*a->get(i)->as_table(), "grass[" + std::to_string(i) + "]", file);
    GrassSettings g;
    g.location = r.location(nullptr);
    g.type = static_cast<int>(r.integer("type", 1, 3));
    if (!types.insert(g.type).second)
      r.fail("type", "grass type " + std::to_string(g.type) + " is defined twice");
    g.density_per_m2 = r.number("density_per_m2", Range{0.0, 2000.0, true}, g.density_per_m2);
    g.blade_length = r.number("blade_length", Range{0.01, 3.0}, g.blade_length);
    g.blade_width = r.number("blade_width", Range{0.0005, 0.05}, g.blade_width);
    g.curvature = r.number("curvature", Range{0.0, 1.0}, g.curvature);
    g.colour = to_vec3f(r.vec3("colour", kUnit, Vec3{0.10, 0.22, 0.05}));
    if (r.has("cover")) g.cover = read_cover(r);
    r.finish();
    out.push_back(g);
  }
  check_fractions(out, *a, "grass", file);
  return out;
}

WindSettings read_wind(const toml::table& t, const std::string& file) {
  TableReader r(t, "wind", file);
  WindSettings w;
  w.speed = r.number("speed", Range{0.0, kMaxWindSpeed}, w.speed);
  w.gust = r.number("gust", Range{0.0, kMaxWindSpeed}, w.gust);
  w.direction_deg = r.number("direction", Range{0.0, 360.0}, w.direction_deg);
  w.gust_scale = r.number("gust_scale", Range{1.0, 100000.0}, w.gust_scale);
  w.phase_groups = static_cast<int>(r.integer("phase_groups", 1, 16, w.phase_groups));
  r.finish();
  return w;
}

}  // namespace landsim::scenes::detail
