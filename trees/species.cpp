#include "trees/species.h"

#include <toml++/toml.h>
#include <pugixml.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <optional>
#include <sstream>
#include <utility>

#include "core/input_error.h"
#include "trees/graph_paths/parameters.h"
#include "trees/harmonic/generator.h"
#include "trees/measured_growth/generator.h"
#include "trees/mesher.h"
#include "trees/self_organizing/generator.h"
#include "trees/weber_penn/generator.h"

namespace landsim::trees {
namespace {

std::string read_text(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in || std::filesystem::is_directory(file))
    throw InputError(file.string() + ": cannot open species file");
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::optional<double> to_number(const std::string& text) {
  std::istringstream in(text);
  double v = 0.0;
  in >> v;
  if (in.fail() || !in.eof()) {
    // Allow trailing blanks, nothing else.
    std::string rest;
    if (in.fail() || (in >> rest, !rest.empty())) return std::nullopt;
  }
  return v;
}

std::string where(const std::string& source, const toml::source_region& r) {
  return source + ":" + std::to_string(r.begin.line) + ":" + std::to_string(r.begin.column);
}

Vec3f read_colour(const toml::node& node, const std::string& source, const std::string& key) {
  const toml::array* a = node.as_array();
  const std::string msg =
      where(source, node.source()) + ": colours." + key + ": expected [r, g, b], each 0 to 1";
  if (a == nullptr || a->size() != 3) throw InputError(msg);
  std::array<float, 3> c{};
  for (std::size_t i = 0; i < 3; ++i) {
    const auto v = a->get(i)->value<double>();
    if (!v || *v < 0.0 || *v > 1.0) throw InputError(msg);
    c[i] = static_cast<float>(*v);
  }
  return {c[0], c[1], c[2]};
}

void read_colours(const toml::node& node, const std::string& source, TreeColours& colours) {
  const toml::table* t = node.as_table();
  if (t == nullptr) throw InputError(where(source, node.source()) + ": colours: expected a table");
  for (auto&& [key, value] : *t) {
    if (key.str() == "bark") {
      colours.bark = read_colour(value, source, "bark");
    } else if (key.str() == "leaf") {
      colours.leaf = read_colour(value, source, "leaf");
    } else if (key.str() == "leaf_weak") {
      colours.leaf_weak = read_colour(value, source, "leaf_weak");
    } else {
      throw InputError(where(source, key.source()) + ": colours: unknown key '" +
                       std::string(key.str()) + "' (expected bark, leaf, leaf_weak)");
    }
  }
}

std::size_t line_of(std::string_view text, std::ptrdiff_t offset) {
  const auto end = text.begin() +
                   std::clamp<std::ptrdiff_t>(offset, 0, static_cast<std::ptrdiff_t>(text.size()));
  return 1 + static_cast<std::size_t>(std::count(text.begin(), end, '\n'));
}

// The cores by their species-file name. Every core but Weber & Penn reads its own tables.
constexpr std::pair<const char*, CoreKind> kCores[] = {
    {"weber_penn", CoreKind::weber_penn},
    {"graph_paths", CoreKind::graph_paths},
    {"self_organizing", CoreKind::self_organizing},
    {"harmonic", CoreKind::harmonic},
    {"measured_growth", CoreKind::measured_growth}};

std::optional<CoreKind> core_named(const std::optional<std::string>& name) {
  for (const auto& [n, kind] : kCores)
    if (name == n) return kind;
  return std::nullopt;
}

// "\"a\", \"b\" or \"c\"": every core's name, for messages.
std::string core_names() {
  std::string list;
  for (std::size_t i = 0; i < std::size(kCores); ++i)
    list += (i == 0                       ? ""
             : i + 1 == std::size(kCores) ? " or "
                                          : ", ") +
            std::string("\"") + kCores[i].first + "\"";
  return list;
}

}  // namespace

std::string core_name(CoreKind core) {
  for (const auto& [n, kind] : kCores)
    if (kind == core) return n;
  return "unknown";
}

Species parse_species_toml(std::string_view text, const std::string& source) {
  toml::table root;
  try {
    root = toml::parse(text, source);
  } catch (const toml::parse_error& e) {
    throw InputError(where(source, e.source()) +
                     ": not valid TOML: " + std::string(e.description()));
  }
  Species s;
  s.source = source;
  s.name = std::filesystem::path(source).stem().string();
  ParamTable params;
  bool has_core = false;
  // Other cores' own tables are read by the core below, not as flat parameters.
  const std::optional<CoreKind> named = core_named(root["core"].value<std::string>());
  const bool own_tables = named && *named != CoreKind::weber_penn;
  for (auto&& [key, value] : root) {
    const std::string k(key.str());
    if (k == "core") {
      if (!named)
        throw InputError(where(source, value.source()) + ": core: expected " + core_names() +
                         " (the cores available)");
      s.core = *named;
      has_core = true;
    } else if (k == "name") {
      const auto name = value.value<std::string>();
      if (!name) throw InputError(where(source, value.source()) + ": name: expected a string");
      s.name = *name;
    } else if (k == "colours") {
      read_colours(value, source, s.colours);
    } else if (own_tables) {
      continue;
    } else {
      RawParam raw;
      raw.where = where(source, value.source());
      if (value.is_number()) {
        raw.number = value.value<double>();
        std::ostringstream t;
        t << *raw.number;
        raw.text = t.str();
      } else if (value.is_string()) {
        raw.text = *value.value<std::string>();
        raw.number = to_number(raw.text);
      } else {
        throw InputError(raw.where + ": parameter " + k +
                         ": expected a number or a string, got another type");
      }
      params.emplace(k, raw);
    }
  }
  if (!has_core)
    throw InputError(source + ": required key 'core' is missing (e.g. core = \"weber_penn\")");
  if (s.core == CoreKind::graph_paths)
    s.parameters = graph_paths::parse_parameters(text, source);
  else if (s.core == CoreKind::self_organizing)
    s.parameters = self_organizing::parse_parameters(text, source);
  else if (s.core == CoreKind::harmonic)
    s.parameters = harmonic::parse_parameters(text, source);
  else if (s.core == CoreKind::measured_growth)
    s.parameters = measured_growth::parse_parameters(text, source);
  else
    s.parameters = weber_penn::parse_parameters(params, source);
  return s;
}

Species parse_arbaro_xml(std::string_view text, const std::string& source) {
  pugi::xml_document doc;
  const pugi::xml_parse_result ok = doc.load_buffer(text.data(), text.size());
  if (!ok) {
    throw InputError(source + ":" + std::to_string(line_of(text, ok.offset)) +
                     ": not valid XML: " + ok.description());
  }
  const pugi::xml_node species = doc.child("arbaro").child("species");
  if (!species)
    throw InputError(source + ": expected <arbaro><species ...> (an Arbaro species file)");
  Species s;
  s.source = source;
  s.name =
      species.attribute("name").as_string(std::filesystem::path(source).stem().string().c_str());
  ParamTable params;
  for (const pugi::xml_node node : species.children("param")) {
    const std::string name = node.attribute("name").as_string();
    RawParam raw;
    raw.where = source + ":" + std::to_string(line_of(text, node.offset_debug()));
    raw.text = node.attribute("value").as_string();
    raw.number = to_number(raw.text);
    if (name.empty()) throw InputError(raw.where + ": <param> without a name");
    params.emplace(name, raw);
  }
  s.parameters = weber_penn::parse_parameters(params, source);
  return s;
}

Species parse_species(std::string_view text, const std::string& source) {
  const std::string ext = std::filesystem::path(source).extension().string();
  if (ext == ".toml") return parse_species_toml(text, source);
  if (ext == ".xml") return parse_arbaro_xml(text, source);
  throw InputError(source + ": unknown species file type (expected .toml, or .xml for Arbaro)");
}

Species load_species(const std::filesystem::path& file) {
  if (const std::string ext = file.extension().string(); ext != ".toml" && ext != ".xml") {
    throw InputError(file.string() +
                     ": unknown species file type (expected .toml, or .xml for Arbaro)");
  }
  return parse_species(read_text(file), file.string());
}

namespace {

void measure(Tree& tree) {
  for (const GroupGeometry& g : tree.geometry.groups) {
    for (const Vec3f& v : g.triangles.vertices) {
      tree.stats.height = std::max(tree.stats.height, static_cast<double>(v.z));
      tree.stats.crown_radius = std::max(
          tree.stats.crown_radius, std::hypot(static_cast<double>(v.x), static_cast<double>(v.y)));
    }
  }
}

void count_stems(const TreeSkeleton& skeleton, std::size_t levels, TreeStats& stats) {
  stats.stems_per_level.assign(levels, 0);
  for (const StemSkeleton& stem : skeleton.stems) {
    if (stem.sections.size() < 2) continue;
    ++stats.stems_per_level[static_cast<std::size_t>(stem.level)];
    stats.clones += stem.clone ? 1 : 0;
  }
  stats.leaves = static_cast<int>(skeleton.leaves.size());
}

// A skeleton of a core without wind sway (wind is a Weber & Penn section 4 model; the
// graph-paths and self-organising trees stand still), meshed.
Tree still_tree(TreeSkeleton skeleton, const Species& species) {
  skeleton.colours = species.colours;
  Tree tree;
  count_stems(skeleton, 4, tree.stats);
  tree.geometry = mesh_tree(skeleton, MeshResolution{});
  measure(tree);
  return tree;
}

}  // namespace

Tree generate(const Species& species, const TreeOptions& options) {
  if (species.core == CoreKind::graph_paths)
    return still_tree(graph_paths::generate_skeleton(
                          std::get<graph_paths::Parameters>(species.parameters), options.seed),
                      species);
  if (species.core == CoreKind::measured_growth)
    return still_tree(
        measured_growth::generate_skeleton(
            std::get<measured_growth::Parameters>(species.parameters), options.seed, options.age),
        species);
  if (species.core == CoreKind::harmonic) {
    // Level of detail for this core: fewer cross-sections per chain at lower quality.
    const int stride = std::max(1, static_cast<int>(std::lround(1.0 / options.quality)));
    return still_tree(
        harmonic::generate_skeleton(std::get<harmonic::Parameters>(species.parameters),
                                    options.seed, {.max_level = 5, .stride = stride}),
        species);
  }
  if (species.core == CoreKind::self_organizing)
    return still_tree(self_organizing::generate_skeleton(
                          std::get<self_organizing::Parameters>(species.parameters), options.seed),
                      species);
  const auto& params = std::get<weber_penn::Parameters>(species.parameters);
  weber_penn::GenerateOptions o;
  o.seed = options.seed;
  o.wind = {options.time, options.wind_speed, options.wind_gust};
  o.quality = options.quality;
  TreeSkeleton skeleton = weber_penn::generate_skeleton(params, o);
  skeleton.colours = species.colours;

  Tree tree;
  count_stems(skeleton, static_cast<std::size_t>(params.levels), tree.stats);
  tree.geometry = mesh_tree(skeleton, weber_penn::mesh_resolution(params));
  measure(tree);
  return tree;
}

}  // namespace landsim::trees
