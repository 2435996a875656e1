#include "scenes/scenario/detail/canopy_reader.h"

#include <set>

#include "params/table_reader.h"
#include "scenes/scenario/detail/relative_path.h"
#include "scenes/scenario/detail/toml_tables.h"
#include "terrain/raster_files.h"

namespace landsim::scenes::detail {
namespace {

using params::Range;
using params::TableReader;

// The text of the file named by `key`, resolved against the scenario's folder.
std::pair<std::string, std::string> text_of(TableReader& r, std::string_view key,
                                            const std::string& base_dir) {
  const std::string path = resolve(base_dir, r.string(key));
  const std::optional<std::string> text = terrain::read_text_file(path);
  if (!text) r.fail(key, "file not found: " + path);
  return {path, *text};
}

// `size` by shape: a radius (sphere), [radius, height] (cylinder, cone) or [x, y, z].
Vec3 read_size(TableReader& r, CloudShape shape) {
  const Range metres{0.0, 1e4, true};
  switch (shape) {
    case CloudShape::sphere: {
      const double radius = r.number("size", metres);
      return {radius, radius, radius};
    }
    case CloudShape::cylinder:
    case CloudShape::cone: {
      const std::vector<double> v = r.numbers("size", 2, metres);
      return {v[0], v[0], v[1]};
    }
    case CloudShape::ellipsoid:
    case CloudShape::box: {
      const std::vector<double> v = r.numbers("size", 3, metres);
      return {v[0], v[1], v[2]};
    }
  }
  return {};
}

GeneratedCloud read_generated(TableReader& r) {
  GeneratedCloud g;
  const std::string shape =
      r.choice("shape", {"sphere", "ellipsoid", "cylinder", "cone", "box"}, "sphere");
  g.shape = shape == "sphere"      ? CloudShape::sphere
            : shape == "ellipsoid" ? CloudShape::ellipsoid
            : shape == "cylinder"  ? CloudShape::cylinder
            : shape == "cone"      ? CloudShape::cone
                                   : CloudShape::box;
  g.size = read_size(r, g.shape);
  g.discs = static_cast<int>(r.integer("discs", 1, kMaxCloudDiscs));
  g.disc_radius = r.number("disc_radius", Range{0.0, 100.0, true});
  const std::string angles =
      r.choice("leaf_angles",
               {"uniform", "planophile", "erectophile", "plagiophile", "extremophile"}, "uniform");
  g.angles = angles == "uniform"       ? LeafAngles::uniform
             : angles == "planophile"  ? LeafAngles::planophile
             : angles == "erectophile" ? LeafAngles::erectophile
             : angles == "plagiophile" ? LeafAngles::plagiophile
                                       : LeafAngles::extremophile;
  g.variants = static_cast<int>(r.integer("variants", 1, 1024, g.variants));
  if (static_cast<double>(g.discs) * g.variants > kMaxCloudDiscs)
    r.fail("variants", "discs x variants must be at most " + std::to_string(kMaxCloudDiscs) +
                           " (each variant is a cloud of its own)");
  return g;
}

// `positions`: a file of `x y z` lines, or an array of [x, y, z]; where each was given.
void read_positions(TableReader& r, const std::string& base_dir, const std::string& file,
                    CanopySettings& c) {
  const toml::node* n = r.value("positions", "a file of x y z lines, or [[x, y, z], ...]");
  if (n == nullptr) r.fail("positions", "required key is missing: a file or [[x, y, z], ...]");
  if (n->is_string()) {
    const auto [path, text] = text_of(r, "positions", base_dir);
    c.positions_file = path;
    c.positions = parse_positions(text, path, &c.position_lines);
    return;
  }
  c.positions_file = file;
  const toml::array* a = n->as_array();
  if (a == nullptr || a->empty() || a->size() > static_cast<std::size_t>(kMaxCanopyCopies))
    r.fail_at(*n, "positions", "expected a file name or [[x, y, z], ...]");
  for (const toml::node& p : *a) {
    const toml::array* xyz = p.as_array();
    if (xyz == nullptr || xyz->size() != 3) r.fail_at(p, "positions", "expected [x, y, z]");
    std::array<double, 3> v{};
    for (std::size_t k = 0; k < 3; ++k) {
      const std::optional<double> x = xyz->get(k)->value<double>();
      if (!x || !std::isfinite(*x)) r.fail_at(p, "positions", "expected numbers [x, y, z]");
      v[k] = *x;
    }
    c.positions.push_back({v[0], v[1], v[2]});
    c.position_lines.push_back(static_cast<std::uint32_t>(p.source().begin.line));
  }
}

CanopySettings read_canopy(TableReader& r, const std::string& base_dir, const std::string& file) {
  CanopySettings c;
  c.location = r.location(nullptr);
  c.name = r.string("name");
  if (r.has("leaves") == r.has("shape"))
    r.fail("leaves", "give either leaves (a disc file) or shape (a generated cloud)");
  if (r.has("leaves")) {
    const auto [path, text] = text_of(r, "leaves", base_dir);
    c.discs = parse_leaf_discs(text, path);
  } else {
    c.generated = read_generated(r);
  }
  read_positions(r, base_dir, file, c);
  c.reflectance = r.number("reflectance", kUnit, c.reflectance);
  c.transmittance = r.number("transmittance", kUnit, c.transmittance);
  if (c.reflectance + c.transmittance > 1.0)
    r.fail("transmittance", "reflectance + transmittance must be at most 1 (energy)");
  if (r.has("trunk")) {
    TableReader t = r.table("trunk");
    CanopyTrunk trunk;
    trunk.radius = t.number("radius", Range{0.0, 100.0, true}, trunk.radius);
    trunk.height = t.number("height", Range{0.0, 1000.0, true}, trunk.height);
    trunk.reflectance = t.number("reflectance", kUnit, trunk.reflectance);
    t.finish();
    c.trunk = trunk;
  }
  r.finish();
  return c;
}

}  // namespace

std::vector<CanopySettings> read_canopies(const toml::table& root, const std::string& file,
                                          const std::string& base_dir) {
  std::vector<CanopySettings> out;
  TableReader top(root, "", file);
  std::set<std::string> names;
  for (TableReader& r : top.tables("canopy")) {
    out.push_back(read_canopy(r, base_dir, file));
    if (!names.insert(out.back().name).second)
      r.fail("name", "the name '" + out.back().name + "' is used by another [[canopy]]");
  }
  return out;
}

}  // namespace landsim::scenes::detail
