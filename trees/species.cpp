#include "trees/species.h"

#include "trees/sway.h"

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
#include "core/input_warnings.h"
#include "params/table_reader.h"
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

void read_colours(params::TableReader t, TreeColours& colours) {
  constexpr params::Range kUnit{0.0, 1.0};
  colours.bark = Vec3f(t.vec3("bark", kUnit, Vec3(colours.bark)));
  colours.leaf = Vec3f(t.vec3("leaf", kUnit, Vec3(colours.leaf)));
  colours.leaf_weak = Vec3f(t.vec3("leaf_weak", kUnit, Vec3(colours.leaf_weak)));
  // A harmonic species' flowers are leaves drawn in the second leaf colour: `flower` names it.
  if (t.has("flower")) {
    if (t.has("leaf_weak")) t.fail("flower", "expected flower or leaf_weak, not both (one colour)");
    colours.leaf_weak = Vec3f(t.vec3("flower", kUnit));
  }
  t.finish();
}

}  // namespace

LeafContents read_leaf_contents(params::TableReader& t) {
  const LeafContents d;
  LeafContents c;
  c.structure = t.number("structure", {1.0, 3.5}, d.structure);
  c.chlorophyll = t.number("chlorophyll", {0.0, 120.0}, d.chlorophyll);
  c.carotenoids = t.number("carotenoids", {0.0, 40.0}, d.carotenoids);
  c.anthocyanins = t.number("anthocyanins", {0.0, 40.0}, d.anthocyanins);
  c.brown = t.number("brown", {0.0, 2.0}, d.brown);
  c.water = t.number("water", {0.0, 0.1}, d.water);
  c.dry_matter = t.number("dry_matter", {0.0, 0.05}, d.dry_matter);
  t.finish();
  return c;
}

namespace {

std::size_t line_of(std::string_view text, std::ptrdiff_t offset) {
  const auto end = text.begin() +
                   std::clamp<std::ptrdiff_t>(offset, 0, static_cast<std::ptrdiff_t>(text.size()));
  return 1 + static_cast<std::size_t>(std::count(text.begin(), end, '\n'));
}

// The cores by their species-file name, in the order of Species::parameters' alternatives.
const std::vector<std::string> kCoreNames = {"weber_penn", "graph_paths", "self_organizing",
                                             "harmonic", "measured_growth"};

}  // namespace

std::string core_name(const Species& species) { return kCoreNames[species.parameters.index()]; }

// [age]: the file's tree's age in years and the height-age curve of younger ones.
void read_age(params::TableReader t, AgeCurve& age) {
  if (const auto m = t.optional_number("mature", {0.0, 1000.0, true})) age.mature = *m;
  age.kappa = t.number("kappa", {0.1, 20.0}, age.kappa);
  age.shape = t.number("shape", {0.1, 5.0}, age.shape);
}

// One growth step a year for the self-organising core (Palubicki et al. 2009's cycles);
// kDefaultMatureAge for the others.
void set_default_mature_age(Species& s) {
  if (s.age.mature >= 0.0) return;
  const auto* so = std::get_if<self_organizing::Parameters>(&s.parameters);
  s.age.mature = so != nullptr ? so->steps : kDefaultMatureAge;
}

Species parse_species_toml(std::string_view text, const std::string& source,
                           params::Declarations* declared) {
  toml::table root;
  try {
    root = toml::parse(text, source);
  } catch (const toml::parse_error& e) {
    throw InputError(params::parse_error_message(e, source));
  }
  if (root.contains("terrain") || root.contains("views"))
    throw InputError(source +
                     ": this is a scenario, not a species file (a species file names its core: "
                     "core = \"weber_penn\", ...); landsim render and info take scenarios");
  params::TableReader r(root, "", source, declared);
  Species s;
  s.source = source;
  const std::string core = r.choice("core", kCoreNames);
  s.name = r.string("name", std::filesystem::path(source).stem().string());
  read_colours(r.table("colours"), s.colours);
  if (r.has("leaf_optics")) {
    params::TableReader optics = r.table("leaf_optics");
    s.colours.leaf_optics = read_leaf_contents(optics);
  }
  if (core == "graph_paths")
    s.parameters = graph_paths::read_parameters(r, source);
  else if (core == "self_organizing")
    s.parameters = self_organizing::read_parameters(r, source);
  else if (core == "harmonic")
    s.parameters = harmonic::read_parameters(r, source);
  else if (core == "measured_growth")
    s.parameters = measured_growth::read_parameters(r, source);
  else
    s.parameters = weber_penn::read_parameters(r, source);
  if (core != "measured_growth") read_age(r.table("age"), s.age);
  set_default_mature_age(s);
  r.finish();
  return s;
}

// Arbaro fills a missing <param> with its default without a word, and so does the reader;
// but a file missing Levels or 1DownAngle is a different tree (5,429 stems became 247). The
// parameters that shape this tree (Weber & Penn's Table 1, for the levels it has) and were
// not given are named once. Arbaro's own additions (ZScale, LeafQuality, nBranchDist, ...)
// and parameters whose default switches a feature off (pruning, lobes) are not: Arbaro's
// example files leave them out routinely.
void warn_arbaro_defaults(const ParamTable& given, const weber_penn::Parameters& p,
                          const std::string& source) {
  std::vector<std::string> wanted = {"Shape", "BaseSize",   "Scale",  "Levels",
                                     "Ratio", "RatioPower", "0Scale", "Leaves"};
  if (p.leaves != 0) wanted.insert(wanted.end(), {"LeafScale", "LeafScaleX"});
  for (int n = 0; n < std::min(p.levels, 4); ++n) {
    const std::string l = std::to_string(n);
    for (const char* k : {"Length", "Taper", "CurveRes", "Curve"}) wanted.push_back(l + k);
    if (n > 0)
      for (const char* k : {"DownAngle", "Rotate", "Branches"}) wanted.push_back(l + k);
  }
  std::string missing;
  int count = 0;
  for (const std::string& name : wanted)
    if (given.count(name) == 0) missing += (count++ == 0 ? "" : ", ") + name;
  if (count > 0)
    warn_input(source + ": " + std::to_string(count) +
               " parameters not given, Arbaro's defaults used: " + missing);
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
    raw.number = param_number(raw.text);
    if (name.empty()) throw InputError(raw.where + ": <param> without a name");
    if (!node.attribute("value"))
      throw InputError(raw.where + ": <param name='" + name +
                       "'> has no value attribute (expected value='...')");
    params.emplace(name, raw);
  }
  const weber_penn::Parameters parameters = weber_penn::parse_parameters(params, source);
  warn_arbaro_defaults(params, parameters, source);
  s.parameters = parameters;
  set_default_mature_age(s);
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

// Height and crown radius: of what stands above the base (a root system spreads below it).
void measure(Tree& tree) {
  for (const GroupGeometry& g : tree.geometry.groups) {
    for (const Vec3f& v : g.triangles.vertices) {
      tree.stats.height = std::max(tree.stats.height, static_cast<double>(v.z));
      if (v.z >= 0.0f)
        tree.stats.crown_radius =
            std::max(tree.stats.crown_radius,
                     std::hypot(static_cast<double>(v.x), static_cast<double>(v.y)));
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

}  // namespace

namespace {

// Every point and radius of `s` times f about the tree's base (leaves keep their size).
void scale_skeleton(TreeSkeleton& s, double f) {
  for (StemSkeleton& stem : s.stems)
    for (CrossSection& c : stem.sections) {
      c.position = c.position * f;
      c.radius *= f;
    }
  for (LeafSkeleton& leaf : s.leaves) leaf.base = leaf.base * f;
}

// Graph paths at `age`: the levels it has reached, the whole tree scaled to its size.
TreeSkeleton graph_paths_at(graph_paths::Parameters p, const AgeCurve& curve, double age,
                            std::uint64_t seed) {
  if (age < 0.0) return graph_paths::generate_skeleton(p, seed);
  p.iteration.levels = levels_at(curve, age, p.iteration.levels + 1) - 1;
  TreeSkeleton s = graph_paths::generate_skeleton(p, seed);
  scale_skeleton(s, size_fraction(curve, age));
  return s;
}

// Weber & Penn at `age`: Scale (and its variation) by the size fraction, Levels by the
// levels reached; everything else is relative to Scale.
weber_penn::Parameters weber_penn_at(weber_penn::Parameters p, const AgeCurve& curve, double age) {
  if (age < 0.0) return p;
  const double f = size_fraction(curve, age);
  p.scale *= f;
  p.scale_v *= f;
  p.levels = levels_at(curve, age, p.levels);
  return p;
}

}  // namespace

TreeSkeleton core_skeleton(const Species& species, const TreeOptions& options) {
  // Measured growth takes its ages itself; the other cores' within [0, mature].
  const bool measured = uses_core<measured_growth::Parameters>(species);
  const double age = options.age >= 0.0 && !measured
                         ? clamp_age(species.age, options.age, species.name.c_str())
                         : -1.0;
  if (const auto* p = std::get_if<graph_paths::Parameters>(&species.parameters))
    return graph_paths_at(*p, species.age, age, options.seed);
  if (const auto* p = std::get_if<measured_growth::Parameters>(&species.parameters))
    return measured_growth::generate_skeleton(*p, options.seed, options.age);
  if (const auto* p = std::get_if<harmonic::Parameters>(&species.parameters)) {
    // Level of detail for this core: fewer cross-sections per chain at lower quality.
    const int stride = std::max(1, static_cast<int>(std::lround(1.0 / options.quality)));
    // Its particles' own age: the share of the individual's max age the tree has lived.
    const double share = age < 0.0 ? 1.0 : age / species.age.mature;
    return harmonic::generate_skeleton(*p, options.seed, {.max_level = 5, .stride = stride},
                                       nullptr, share);
  }
  if (const auto* p = std::get_if<self_organizing::Parameters>(&species.parameters)) {
    self_organizing::Parameters young = *p;
    young.steps = self_organizing_steps(species, age);
    return self_organizing::generate_skeleton(young, options.seed);
  }
  weber_penn::GenerateOptions o;
  o.seed = options.seed;
  o.quality = options.quality;
  return weber_penn::generate_skeleton(
      weber_penn_at(std::get<weber_penn::Parameters>(species.parameters), species.age, age), o);
}

namespace {

// A core's skeleton swayed, coloured, counted and meshed.
Tree finish(TreeSkeleton skeleton, const Species& species, const TreeOptions& options) {
  // Wind sway (Weber & Penn section 4.7), the same for every core (trees/sway.h); the phases
  // from the tree's seed.
  apply_sway(skeleton, {options.time, options.wind_speed, options.wind_gust,
                        options.sway_seed != 0 ? options.sway_seed : options.seed});
  skeleton.colours = species.colours;
  const auto* wp = std::get_if<weber_penn::Parameters>(&species.parameters);
  Tree tree;
  count_stems(skeleton, wp != nullptr ? static_cast<std::size_t>(wp->levels) : 4, tree.stats);
  tree.geometry =
      mesh_tree(skeleton, wp != nullptr ? weber_penn::mesh_resolution(*wp) : MeshResolution{});
  measure(tree);
  return tree;
}

}  // namespace

int self_organizing_steps(const Species& species, double age) {
  const int steps = std::get<self_organizing::Parameters>(species.parameters).steps;
  if (age < 0.0) return steps;
  return steps_at(species.age, clamp_age(species.age, age, species.name.c_str()), steps);
}

Tree generate(const Species& species, const TreeOptions& options) {
  return finish(core_skeleton(species, options), species, options);
}

std::vector<Tree> generate_ages(const Species& species, const TreeOptions& options,
                                const std::vector<double>& ages) {
  std::vector<Tree> trees;
  const auto* so = std::get_if<self_organizing::Parameters>(&species.parameters);
  if (so == nullptr) {
    for (double age : ages) {
      TreeOptions o = options;
      o.age = age;
      trees.push_back(generate(species, o));
    }
    return trees;
  }
  // Self-organising: grown once, each age recovered from the time stamps.
  std::vector<int> steps;
  for (double age : ages) steps.push_back(self_organizing_steps(species, age));
  std::vector<TreeSkeleton> skeletons =
      self_organizing::skeletons_at_steps(*so, options.seed, steps);
  for (TreeSkeleton& s : skeletons) trees.push_back(finish(std::move(s), species, options));
  return trees;
}

}  // namespace landsim::trees
