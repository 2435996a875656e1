#include "scenes/scenario/detail/ground_reader.h"

#include <optional>
#include <utility>
#include <vector>

#include "params/table_reader.h"
#include "scenes/scenario/detail/relative_path.h"
#include "scenes/scenario/detail/toml_tables.h"
#include "terrain/raster_files.h"

namespace landsim::scenes::detail {

namespace {

using params::Range;
using params::TableReader;

// Ground material names in [ground] and their ids (renderer/materials/ground_shading.h); "grass" is
// the ground under all three grass types.
const std::vector<std::pair<std::string, std::vector<int>>> kGroundNames{
    {"terrain", {0}}, {"road", {1}},        {"water", {2}},       {"rock", {3}},
    {"soil", {4}},    {"grass", {5, 6, 7}}, {"surroundings", {8}}};

// The ids of the material named `name` (a value, or a table key when `name` is given), with
// `n` locating the message.
std::vector<int> ground_ids(const TableReader& r, const toml::node& n, std::string_view key,
                            std::optional<std::string> name = std::nullopt) {
  if (!name) name = n.value<std::string>();
  for (const auto& [known, ids] : kGroundNames)
    if (name && *name == known) return ids;
  r.fail_at(n, key,
            "unknown ground material " + (name ? "'" + *name + "'" : params::type_name(n)) +
                " (expected terrain, road, water, rock, soil, grass or surroundings)");
}

// A number for every material but water, or { material = number, ... }: `key` of [ground].
void read_per_material(TableReader& r, std::string_view key, const std::string& expected,
                       const std::string& fallback, Range range,
                       std::array<float, renderer::kGroundMaterials>& out) {
  const toml::node* n = r.value(key, expected, fallback);
  if (n == nullptr) return;
  const auto number = [&](const toml::node& v) {
    const std::optional<double> f = v.value<double>();
    if (!f || !range.contains(*f)) r.fail_at(v, key, "expected " + range.describe());
    return static_cast<float>(*f);
  };
  if (const toml::table* t = n->as_table()) {
    for (auto&& [name, value] : *t)
      for (int id : ground_ids(r, value, key, std::string(name.str())))
        out[static_cast<std::size_t>(id)] = number(value);
    return;
  }
  const float f = number(*n);
  for (std::size_t id = 0; id < out.size(); ++id)
    if (id != 2) out[id] = f;
}

renderer::GroundRule read_rule(TableReader& r) {
  renderer::GroundRule rule;
  const std::string m = r.choice("measure", {"slope", "height", "sun_facing"});
  rule.measure = m == "slope"    ? renderer::TerrainMeasure::slope
                 : m == "height" ? renderer::TerrainMeasure::height
                                 : renderer::TerrainMeasure::sun_facing;
  const Range any{-1e7, 1e7};
  if (const auto a = r.optional_number("above", any)) rule.above = *a;
  if (const auto b = r.optional_number("below", any)) rule.below = *b;
  if (!r.has("above") && !r.has("below")) r.fail("measure", "give above, below or both");
  rule.softness = r.number("softness", Range{0.0, 1e6}, rule.softness);
  const toml::node* on = r.value("on", "an array of ground material names",
                                 "[\"terrain\", \"soil\", \"rock\", \"grass\", \"surroundings\"]");
  if (on == nullptr) {
    rule.on = 0b111111001;  // all but road and water
  } else if (const toml::array* a = on->as_array()) {
    for (const toml::node& n : *a)
      for (int id : ground_ids(r, n, "on")) rule.on |= static_cast<std::uint16_t>(1u << id);
  } else {
    r.fail_at(*on, "on", "expected an array of ground material names");
  }
  if (const toml::node* to = r.value("becomes", "a ground material name", "")) {
    const std::vector<int> ids = ground_ids(r, *to, "becomes");
    rule.becomes = ids.front();
  }
  rule.tint = to_vec3f(r.vec3("tint", Range{0.0, 4.0}, Vec3{1.0, 1.0, 1.0}));
  if (rule.becomes < 0 && !r.has("tint"))
    r.fail("measure", "a rule must change something: give becomes, tint or both");
  r.finish();
  return rule;
}

// textures = { rock = "rock.jpg", soil = "soil.png" }: files checked to exist.
void read_textures(TableReader& r, const std::string& base_dir, GroundMaterials& g) {
  const toml::node* n = r.value("textures", "a table of material = image file", "");
  if (n == nullptr) return;
  const toml::table* t = n->as_table();
  if (t == nullptr) r.fail_at(*n, "textures", "expected a table such as { rock = \"rock.jpg\" }");
  for (auto&& [name, value] : *t) {
    if (!value.is_string()) r.fail_at(value, "textures", "expected an image file name");
    const std::string path = resolve(base_dir, *value.value<std::string>());
    if (!terrain::raster_file_exists(path)) r.fail_at(value, "textures", "file not found: " + path);
    for (int id : ground_ids(r, value, "textures", std::string(name.str()))) {
      g.texture_files[static_cast<std::size_t>(id)] = path;
      g.texture_locations[static_cast<std::size_t>(id)] = r.location(&value);
    }
  }
}

// One [[ground.brdf]] table: a model and its parameters, on the materials it names (all
// but water by default); later tables override earlier ones on the materials they share.
void read_brdf(TableReader& r, GroundMaterials& g) {
  renderer::GroundBrdf b;
  const std::string model = r.choice("model", {"lambert", "rpv", "ross-li"});
  const auto refuse = [&](std::initializer_list<const char*> keys, const std::string& why) {
    for (const char* k : keys)
      if (r.has(k)) r.fail(k, why);
  };
  if (model == "rpv") {
    b.model = renderer::GroundBrdf::Model::rpv;
    b.k = static_cast<float>(r.number("k", Range{0.0, 3.0, true}, 1.0));
    b.asymmetry = static_cast<float>(r.number("asymmetry", Range{-1.0, 1.0, true, true}, 0.0));
    if (const auto c = r.optional_number("hot_spot", kUnit)) b.hot_spot = static_cast<float>(*c);
    refuse({"volumetric", "geometric"},
           "a Ross-Li weight; model = \"rpv\" takes k, asymmetry "
           "and hot_spot");
  } else if (model == "ross-li") {
    b.model = renderer::GroundBrdf::Model::ross_li;
    const Range weight{-100.0, 100.0};
    b.volumetric = static_cast<float>(r.number("volumetric", weight, 0.0));
    b.geometric = static_cast<float>(r.number("geometric", weight, 0.0));
    refuse({"k", "asymmetry", "hot_spot"},
           "an RPV parameter; model = \"ross-li\" takes volumetric and geometric");
  } else {
    refuse({"k", "asymmetry", "hot_spot", "volumetric", "geometric"},
           "model = \"lambert\" has no parameters");
  }
  const bool white_sky = !b.lambertian() && r.choice("reflectance", {"white-sky", "isotropic"},
                                                     "white-sky") == "white-sky";
  if (b.lambertian() && r.has("reflectance"))
    r.fail("reflectance", "model = \"lambert\" reflects its reflectance whatever it stands for");
  std::uint16_t on = 0b111111011;  // all but water
  if (const toml::node* n =
          r.value("on", "an array of ground material names", "every material but water")) {
    const toml::array* a = n->as_array();
    if (a == nullptr) r.fail_at(*n, "on", "expected an array of ground material names");
    on = 0;
    for (const toml::node& m : *a)
      for (int id : ground_ids(r, m, "on")) {
        if (id == 2)
          r.fail_at(m, "on",
                    "water reflects as a Fresnel mirror over a dark body; a "
                    "reflectance model does not apply to it");
        on |= static_cast<std::uint16_t>(1u << id);
      }
  }
  const std::string where = r.location(nullptr);
  for (std::size_t id = 0; id < g.brdf.size(); ++id)
    if (on & (1u << id)) {
      g.brdf[id] = b;
      g.brdf_white_sky[id] = white_sky;
      g.brdf_locations[id] = where;
    }
  r.finish();
}

}  // namespace

GroundMaterials read_ground(const toml::table& root, const std::string& file,
                            const std::string& base_dir) {
  GroundMaterials g;
  TableReader r(sub_table(root, "ground", file, false), "ground", file);
  g.soil = to_vec3f(r.vec3("soil", kUnit, Vec3(g.soil)));
  g.rock = to_vec3f(r.vec3("rock", kUnit, Vec3(g.rock)));
  g.water = to_vec3f(r.vec3("water", kUnit, Vec3(g.water)));
  g.road = to_vec3f(r.vec3("road", kUnit, Vec3(g.road)));
  g.soil_moisture = r.number("soil_moisture", kUnit, g.soil_moisture);
  g.flat_soil = r.choice("soil_spectrum", {"measured", "flat"}, "measured") == "flat";
  if (g.flat_soil && r.has("soil_moisture"))
    r.fail("soil_moisture", "a flat soil spectrum has no moisture (soil_spectrum = \"flat\")");
  // A benchmark's soil is one Lambertian albedo everywhere: no variation unless asked for.
  if (g.flat_soil) g.shading.variation.fill(0.0f);
  read_per_material(r, "variation", "a fraction 0-1, or a table of material = fraction",
                    "0.15 (road 0.05, rock 0.2, water 0)", kUnit, g.shading.variation);
  if (const auto sc = r.optional_numbers("variation_scales", 2, kPositive))
    g.shading.scales = {(*sc)[0], (*sc)[1]};
  for (TableReader& rule : r.tables("rules")) g.shading.rules.push_back(read_rule(rule));
  for (TableReader& brdf : r.tables("brdf")) read_brdf(brdf, g);
  read_textures(r, base_dir, g);
  g.shading.texture_size = r.number("texture_size", kPositive, g.shading.texture_size);
  g.detail = r.boolean("detail", g.detail);
  read_per_material(r, "detail_amplitude", "metres 0-50, or a table of material = metres",
                    "0.3 (rock 1.0, grass 0.2, road, water and surroundings 0)", Range{0.0, 50.0},
                    g.detail_amplitude);
  read_per_material(r, "detail_roughness", "a fraction 0-1, or a table of material = fraction",
                    "0.5 (rock 0.6)", kUnit, g.detail_roughness);
  r.finish();
  return g;
}

}  // namespace landsim::scenes::detail
