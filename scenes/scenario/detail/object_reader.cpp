#include "scenes/scenario/detail/object_reader.h"

#include <cmath>
#include <filesystem>
#include <set>

#include "params/table_reader.h"
#include "scenes/scenario/detail/relative_path.h"
#include "scenes/scenario/detail/toml_tables.h"

namespace landsim::scenes::detail {

namespace {

// Copies one [[objects]] entry may ask for: each is placed by its own search.
constexpr std::int64_t kMaxObjectCount = 1000;

using params::Range;
using params::TableReader;

// [[objects.material]] tables of one object: overrides of its mesh's materials by name.
std::vector<ObjectMaterialOverride> read_object_materials(TableReader& r) {
  std::vector<ObjectMaterialOverride> out;
  std::set<std::string> names;
  for (TableReader& m : r.tables("material")) {
    ObjectMaterialOverride o;
    o.location = m.location(nullptr);
    o.material = m.string("name");
    if (!names.insert(o.material).second)
      m.fail("name", "material '" + o.material + "' is overridden twice");
    if (const auto a = m.optional_numbers("albedo", 3, kUnit))
      o.albedo = Vec3f{static_cast<float>((*a)[0]), static_cast<float>((*a)[1]),
                       static_cast<float>((*a)[2])};
    if (const auto v = m.optional_number("roughness", kUnit)) o.roughness = static_cast<float>(*v);
    if (const auto v = m.optional_number("metallic", kUnit)) o.metallic = static_cast<float>(*v);
    m.finish();
    out.push_back(std::move(o));
  }
  return out;
}

// `position`: [x, y] (standing on the ground) or [x, y, z], terrain coordinates.
void read_object_position(TableReader& r, ObjectSettings& o) {
  const toml::node* n = r.value("position", "[x, y] or [x, y, z], terrain coordinates", "");
  if (n == nullptr) r.fail("position", "required key is missing: give [x, y] or [x, y, z]");
  o.position_location = r.location(n);
  const toml::array* a = n->as_array();
  if (a == nullptr || (a->size() != 2 && a->size() != 3))
    r.fail_at(*n, "position", "expected [x, y] or [x, y, z] (terrain coordinates, metres)");
  std::array<double, 3> v{};
  for (std::size_t k = 0; k < a->size(); ++k) {
    const std::optional<double> x = a->get(k)->value<double>();
    if (!x || !std::isfinite(*x))
      r.fail_at(*a->get(k), "position", "expected a number, got " + params::type_name(*a->get(k)));
    v[k] = *x;
  }
  o.x = v[0];
  o.y = v[1];
  if (a->size() == 3) o.z = v[2];
}

// `heading`: degrees, or "random" (drawn from the seed, uniform all round).
void read_object_heading(TableReader& r, ObjectSettings& o) {
  const toml::node* n = r.value("heading", "degrees -360 to 360, or \"random\"", "0");
  if (n == nullptr) return;
  if (const auto word = n->value<std::string>()) {
    if (*word != "random")
      r.fail_at(*n, "heading",
                "expected degrees (-360 to 360) or \"random\", got \"" + *word + "\"");
    o.random_heading = true;
    return;
  }
  o.heading_deg = r.number("heading", Range{-360.0, 360.0});
}

// [objects.place]: drawn onto ground a view sees, within a range band and bearing sector.
ObjectSiting read_object_siting(TableReader p) {
  ObjectSiting s;
  s.location = p.location(nullptr);
  s.view = p.string("view");
  const std::vector<double> range = p.numbers("range", 2, Range{0.0, 1e6});
  if (!(range[0] < range[1]))
    p.fail("range", "expected [nearest, farthest] metres with nearest < farthest");
  s.range_min = range[0];
  s.range_max = range[1];
  if (const auto b = p.optional_numbers("bearing", 2, Range{-180.0, 180.0})) {
    if (!((*b)[0] < (*b)[1]))
      p.fail("bearing", "expected [from, to] degrees from the view's axis with from < to");
    s.bearing_min = (*b)[0];
    s.bearing_max = (*b)[1];
    s.bearing_given = true;
  }
  s.min_visible = p.number("min_visible", Range{0.0, 1.0, true}, s.min_visible);
  s.trees = p.boolean("trees", s.trees);
  s.seed = static_cast<std::uint64_t>(p.integer("seed", 0, INT64_MAX, 0));
  p.finish();
  return s;
}

}  // namespace

// [[objects]]: meshes placed on the terrain; names unique, files present.
std::vector<ObjectSettings> read_objects(const toml::table& root, const std::string& file,
                                         const std::string& base_dir) {
  std::vector<ObjectSettings> out;
  const toml::array* a = tables(root, "objects", file);
  if (a == nullptr) return out;
  std::set<std::string> names;
  for (std::size_t i = 0; i < a->size(); ++i) {
    const toml::table& t = *a->get(i)->as_table();
    TableReader r(t, "objects[" + std::to_string(i) + "]", file);
    ObjectSettings o;
    o.path = "objects[" + std::to_string(i) + "]";
    o.location = r.location(nullptr);
    o.name = r.string("name");
    if (o.name.empty()) r.fail("name", "expected a name (a non-empty string)");
    if (!names.insert(o.name).second)
      r.fail("name", "the name '" + o.name + "' is used by another object (names must be unique)");
    o.file = resolve(base_dir, r.string("file"));
    o.file_location = r.location(t.get("file"));
    if (!std::filesystem::is_regular_file(o.file))
      r.fail("file", "file not found: " + o.file + " (expected a mesh: OBJ, PLY, glTF or GLB)");
    if (r.has("place")) {
      if (r.has("position"))
        r.fail("position", "give either position or [objects.place], not both");
      o.siting = read_object_siting(r.table("place"));
    } else {
      read_object_position(r, o);
    }
    read_object_heading(r, o);
    const auto count = r.integer("count", 1, kMaxObjectCount, 1);
    if (count > 1 && !o.siting)
      r.fail("count", "copies need [objects.place] to draw where each one stands");
    o.scale = r.number("scale", Range{0.0, 1000.0, true}, o.scale);
    o.unit_scale = r.number("unit_scale", Range{0.0, 1e6, true}, o.unit_scale);
    o.z_up = r.choice("up_axis", {"y", "z"}, "y") == "z";
    o.align_to_ground = r.boolean("align_to_ground", o.align_to_ground);
    o.clear_radius = r.optional_number("clear_radius", Range{0.0, 10000.0});
    o.materials = read_object_materials(r);
    r.finish();
    if (count == 1) {
      out.push_back(std::move(o));
      continue;
    }
    // `count` copies: "<name>_1" ... "<name>_<count>", each its own target id and draw.
    for (std::int64_t k = 0; k < count; ++k) {
      ObjectSettings copy = o;
      copy.name = o.name + "_" + std::to_string(k + 1);
      copy.copy = static_cast<std::size_t>(k);
      if (!names.insert(copy.name).second)
        r.fail("count", "the copy's name '" + copy.name + "' is used by another object");
      out.push_back(std::move(copy));
    }
  }
  return out;
}

}  // namespace landsim::scenes::detail
