#include "trees/graph_paths/parameters.h"

#include "trees/graph_paths/poisson_disc.h"

#include <toml++/toml.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

#include "core/input_error.h"
#include "params/table_reader.h"

namespace landsim::trees::graph_paths {
namespace {

using params::Range;
using params::TableReader;

constexpr Range kCoordinate{-1e4, 1e4};

PrimitiveKind kind_of(const std::string& s) {
  if (s == "cylinder") return PrimitiveKind::cylinder;
  if (s == "cone") return PrimitiveKind::cone;
  if (s == "sphere") return PrimitiveKind::sphere;
  if (s == "sphere_portion") return PrimitiveKind::sphere_portion;
  if (s == "ellipsoid") return PrimitiveKind::ellipsoid;
  return PrimitiveKind::revolution;
}

// A direction: three numbers, not all zero.
Vec3 direction(TableReader& r, std::string_view key, const Vec3& fallback) {
  const Vec3 v = r.vec3(key, kCoordinate, fallback);
  if (!(length(v) > 1e-9)) r.fail(key, "expected a direction, not [0, 0, 0]");
  return v;
}

// [[height, radius], ...]: heights strictly increasing, radii 0-1000 m.
std::vector<ProfilePoint> read_profile(TableReader& r) {
  const std::string expected =
      "[[height, radius], ...]: at least two points, heights strictly increasing, radii 0 to 1000";
  const toml::node* n = r.value("profile", expected);
  std::vector<ProfilePoint> profile;
  if (n == nullptr) return profile;
  const toml::array* a = n->as_array();
  if (a == nullptr || a->size() < 2) r.fail("profile", "expected " + expected);
  for (const toml::node& point : *a) {
    const toml::array* hr = point.as_array();
    const auto h = hr != nullptr && hr->size() == 2 ? hr->get(0)->value<double>() : std::nullopt;
    const auto rad = hr != nullptr && hr->size() == 2 ? hr->get(1)->value<double>() : std::nullopt;
    if (!h || !rad || !(*h >= -1e3 && *h <= 1e3) || !(*rad >= 0 && *rad <= 1e3) ||
        (!profile.empty() && !(*h > profile.back().height)))
      r.fail_at(point, "profile", "expected " + expected);
    profile.push_back({*h, *rad});
  }
  return profile;
}

// [[x, y, z], ...] metres: endpoints the modeler places.
std::vector<Vec3> read_points(TableReader& r, std::string_view key) {
  const std::string expected = "[[x, y, z], ...] in metres";
  const toml::node* n = r.value(key, expected);
  std::vector<Vec3> points;
  if (n == nullptr) return points;
  const toml::array* a = n->as_array();
  if (a == nullptr) r.fail(key, "expected " + expected);
  for (const toml::node& point : *a) {
    const toml::array* q = point.as_array();
    std::optional<double> c[3];
    for (int k = 0; k < 3 && q != nullptr && q->size() == 3; ++k) c[k] = q->get(k)->value<double>();
    if (!c[0] || !c[1] || !c[2] || !kCoordinate.contains(*c[0]) || !kCoordinate.contains(*c[1]) ||
        !kCoordinate.contains(*c[2]))
      r.fail_at(point, key, "expected " + expected);
    points.push_back({*c[0], *c[1], *c[2]});
  }
  return points;
}

VolumePrimitive read_primitive(TableReader& r) {
  VolumePrimitive s;
  s.kind = kind_of(r.choice(
      "kind", {"cylinder", "cone", "sphere", "sphere_portion", "ellipsoid", "revolution"}));
  s.origin = r.vec3("origin", kCoordinate, s.origin);
  s.axis = normalize(direction(r, "axis", s.axis));
  s.radius = r.number("radius", {1e-3, 1e3}, s.radius);
  s.height = r.number("height", {1e-3, 1e3}, s.height);
  s.half_angle = r.angle("half_angle", {1, 180}, s.half_angle);
  s.radii = r.vec3("radii", {1e-3, 1e3}, s.radii);
  s.profile = read_profile(r);
  if (s.kind == PrimitiveKind::revolution && s.profile.size() < 2)
    r.fail("profile", "expected [[height, radius], ...] with at least two points for a revolution");
  r.finish();
  return s;
}

void read_graph(TableReader r, Parameters& p) {
  p.spacing = r.number("spacing", {1e-3, 100}, p.spacing);
  p.policy = r.choice("policy", {"yao", "threshold"}, "yao") == "yao" ? GraphPolicy::yao
                                                                      : GraphPolicy::threshold;
  p.cone_subdivisions = static_cast<int>(r.integer("cone_subdivisions", 3, 8, p.cone_subdivisions));
  p.search_radius = r.number("search_radius", {1.5, 10}, p.search_radius);
  p.threshold = r.number("threshold", {1.0, 10}, p.threshold);
  p.weight_noise = r.number("weight_noise", {0, 10}, p.weight_noise);
  p.root = r.vec3("root", kCoordinate, p.root);
  p.endpoints = static_cast<int>(r.integer("endpoints", 1, 100000, p.endpoints));
  p.shell = r.number("shell", {1e-3, 100}, p.shell);
  p.endpoint_min_z = r.optional_number("endpoint_min_z", kCoordinate).value_or(p.endpoint_min_z);
  p.manual_endpoints = read_points(r, "manual_endpoints");
  r.finish();
}

void read_thickness(TableReader r, SkeletonOptions& o) {
  o.thickness_power = r.number("power", {0.1, 5}, o.thickness_power);
  o.radius_scale = r.number("radius_scale", {1e-5, 10}, o.radius_scale);
  o.min_radius = r.number("min_radius", {1e-4, 1}, o.min_radius);
  r.finish();
}

void read_leaves(TableReader r, SkeletonOptions& o) {
  o.leaves_per_endpoint = static_cast<int>(r.integer("per_endpoint", 0, 64, o.leaves_per_endpoint));
  o.leaf_length = r.number("length", {1e-3, 5}, o.leaf_length);
  o.leaf_width = r.number("width", {1e-3, 5}, o.leaf_width);
  r.finish();
}

Orientation orientation_of(const std::string& s) {
  return s == "down" ? Orientation::down : s == "up" ? Orientation::up : Orientation::along;
}

// One [[iteration.level]] row: only what it names.
LevelSettings read_level(TableReader& r) {
  LevelSettings s;
  s.radius = r.optional_number("radius", {1e-3, 100});
  if (r.has("half_angle")) s.half_angle = r.angle("half_angle", {5, 180}, 0.0);
  s.spacing_ratio = r.optional_number("spacing_ratio", {0.05, 1});
  if (r.has("endpoints")) s.endpoints = static_cast<int>(r.integer("endpoints", 1, 64));
  s.shell = r.optional_number("shell", {0.01, 1});
  if (r.has("rotation")) s.rotation = r.angle("rotation", {-90, 90}, 0.0);
  s.power = r.optional_number("power", {0.1, 5});
  if (r.has("orientation"))
    s.orientation = orientation_of(r.choice("orientation", {"along", "down", "up"}));
  s.every_endpoint = r.boolean("every_endpoint", false);
  r.finish();
  return s;
}

void read_iteration(TableReader r, IterationParameters& it) {
  for (TableReader& row : r.tables("level")) it.table.push_back(read_level(row));
  const auto rows = static_cast<std::int64_t>(it.table.size());
  it.levels = static_cast<int>(r.integer("levels", 0, 7, rows > 0 ? rows : it.levels));
  if (it.levels < rows)
    r.fail("levels", "expected at least " + std::to_string(rows) +
                         " (one level per [[iteration.level]] row), not " +
                         std::to_string(it.levels));
  it.radius = r.number("radius", {1e-3, 100}, it.radius);
  it.size_ratio = r.number("size_ratio", {0.05, 1}, it.size_ratio);
  it.half_angle = r.angle("half_angle", {5, 180}, it.half_angle);
  it.spacing_ratio = r.number("spacing_ratio", {0.05, 1}, it.spacing_ratio);
  it.endpoints = static_cast<int>(r.integer("endpoints", 1, 64, it.endpoints));
  it.shell = r.number("shell", {0.01, 1}, it.shell);
  it.rotation = r.angle("rotation", {-90, 90}, it.rotation);
  if (const auto lifespan = r.optional_number("lifespan", {0, 20})) {
    it.lifespan = *lifespan;
    it.use_lifespan = true;
  }
  it.terminate_probability = r.number("terminate_probability", {0, 1}, it.terminate_probability);
  it.power = r.number("power", {0.1, 5}, it.power);
  it.light = direction(r, "light", it.light);
  it.light_strength = r.number("light_strength", {0, 1}, it.light_strength);
  r.finish();
}

void read_roots(TableReader r, RootParameters& roots) {
  roots.radius = r.number("radius", {0.01, 100}, roots.radius);
  roots.depth = r.number("depth", {0.01, 100}, roots.radius);
  roots.spacing = r.number("spacing", {1e-3, 100}, 0.0);
  roots.taproot = r.boolean("taproot", roots.taproot);
  roots.laterals = static_cast<int>(r.integer("laterals", 0, 10000, roots.laterals));
  roots.shell = r.number("shell", {0.01, 1}, roots.shell);
  roots.levels = static_cast<int>(r.integer("levels", 0, 4, roots.levels));
  roots.level_radius = r.number("level_radius", {0.05, 1}, roots.level_radius);
  roots.level_endpoints =
      static_cast<int>(r.integer("level_endpoints", 1, 64, roots.level_endpoints));
  roots.power = r.number("power", {0.1, 5}, roots.power);
  if (r.has("radius") && roots.laterals == 0 && !roots.taproot)
    r.fail("laterals", "expected at least 1 when taproot = false (no root would grow)");
  r.finish();
}

void read_refinement(TableReader r, Parameters& p) {
  p.refinement.spheres = static_cast<int>(r.integer("spheres", 0, 32, p.refinement.spheres));
  p.refinement.radius = r.number("radius", {0.01, 100}, p.refinement.radius);
  p.refinement.cone_ratio = r.number("cone_ratio", {0.05, 1}, p.refinement.cone_ratio);
  p.refinement.separation = r.number("separation", {0.5, 4}, p.refinement.separation);
  p.junction = r.vec3("junction", kCoordinate, p.junction);
  r.finish();
}

double primitive_volume(const VolumePrimitive& s) {
  constexpr double pi = std::numbers::pi;
  switch (s.kind) {
    case PrimitiveKind::cylinder:
      return pi * s.radius * s.radius * s.height;
    case PrimitiveKind::cone:
      return pi * s.radius * s.radius * s.height / 3;
    case PrimitiveKind::sphere:
      return 4 * pi * std::pow(s.radius, 3) / 3;
    case PrimitiveKind::sphere_portion:
      return 2 * pi * std::pow(s.radius, 3) * (1 - std::cos(s.half_angle)) / 3;
    case PrimitiveKind::ellipsoid:
      return 4 * pi * s.radii.x * s.radii.y * s.radii.z / 3;
    case PrimitiveKind::revolution: {
      double v = 0.0;  // frusta between profile points
      for (std::size_t k = 1; k < s.profile.size(); ++k) {
        const ProfilePoint& a = s.profile[k - 1];
        const ProfilePoint& b = s.profile[k];
        v += pi * (b.height - a.height) *
             (a.radius * a.radius + a.radius * b.radius + b.radius * b.radius) / 3;
      }
      return v;
    }
  }
  return 0.0;
}

}  // namespace

namespace {

// The crown's (or a root system's) own graph nodes, without the roots.
double graph_nodes(const Parameters& p) {
  double v = 0.0;
  for (const VolumePrimitive& s : p.volume.parts()) v += primitive_volume(s);
  // Refinement replaces the volume's fill by its spheres (and their thin cones).
  if (p.refinement.spheres > 0)
    v = p.refinement.spheres * 4.0 * std::numbers::pi * std::pow(p.refinement.radius, 3) / 3.0;
  double nodes = kNodesPerCubicSpacing * v / std::pow(p.spacing, 3);
  // Every endpoint of a level grows a subgraph at the next (a level with every_endpoint at
  // the earlier levels' too), each with the same node count (radius and spacing shrink
  // together); the light can raise endpoint counts by 1 + strength.
  double subgraphs = p.endpoints + static_cast<double>(p.manual_endpoints.size());
  double earlier = 0.0;
  for (const Level& level : resolve_levels(p.iteration)) {
    VolumePrimitive sector;
    sector.kind = PrimitiveKind::sphere_portion;
    sector.radius = 1.0;
    sector.half_angle = level.half_angle;
    const double per_subgraph =
        kNodesPerCubicSpacing * primitive_volume(sector) / std::pow(level.spacing_ratio, 3);
    const double growing = subgraphs + (level.every_endpoint ? earlier : 0.0);
    nodes += growing * per_subgraph;
    earlier += subgraphs;
    subgraphs = growing * level.endpoints * (1.0 + p.iteration.light_strength);
  }
  return nodes;
}

double root_nodes(const Parameters& p) {
  return p.roots.radius > 0.0 ? graph_nodes(root_parameters(p)) : 0.0;
}

}  // namespace

double estimated_nodes(const Parameters& p) { return graph_nodes(p) + root_nodes(p); }

Parameters read_parameters(params::TableReader& root, const std::string& source) {
  Parameters p;
  read_graph(root.table("graph"), p);
  read_thickness(root.table("thickness"), p.skeleton);
  read_leaves(root.table("leaves"), p.skeleton);
  read_iteration(root.table("iteration"), p.iteration);
  read_refinement(root.table("refinement"), p);
  read_roots(root.table("roots"), p.roots);
  std::vector<VolumePrimitive> parts;
  for (TableReader& t : root.tables("volume")) parts.push_back(read_primitive(t));
  if (parts.empty()) throw InputError(source + ": at least one [[volume]] is required");
  p.volume = InitialVolume(std::move(parts));
  for (std::size_t i = 0; i < p.manual_endpoints.size(); ++i) {
    const Vec3& q = p.manual_endpoints[i];
    if (!p.volume.contains(q))
      throw InputError(source + ": [graph] manual_endpoints[" + std::to_string(i) + "] (" +
                       params::format_number(q.x) + ", " + params::format_number(q.y) + ", " +
                       params::format_number(q.z) + ") is outside every [[volume]]");
  }
  const double crown = graph_nodes(p), roots = root_nodes(p);
  const auto about = [&](double n) {
    return "would make about " + std::to_string(static_cast<long long>(n)) +
           " graph nodes in all (limit " + std::to_string(p.max_nodes) + ")";
  };
  // The part that makes most of them is named, at its keys.
  if (crown + roots > static_cast<double>(p.max_nodes) && roots > crown)
    root.table("roots").fail(
        "spacing", "[roots] spacing " + params::format_number(root_parameters(p).spacing) +
                       " with radius " + params::format_number(p.roots.radius) + ", depth " +
                       params::format_number(p.roots.depth) + " and " +
                       std::to_string(p.roots.levels) + " levels " + about(crown + roots) + ", " +
                       std::to_string(static_cast<long long>(roots)) +
                       " of them roots; raise [roots] spacing, or lower [roots] radius, depth, "
                       "levels or level_endpoints");
  if (crown + roots > static_cast<double>(p.max_nodes))
    root.table("graph").fail(
        "spacing", "[graph] spacing " + params::format_number(p.spacing) + " and " +
                       std::to_string(p.iteration.levels) + " [iteration] levels " +
                       about(crown + roots) +
                       "; raise [graph] spacing or [iteration] spacing_ratio, or lower [graph] "
                       "endpoints, [iteration] endpoints or levels");
  return p;
}

}  // namespace landsim::trees::graph_paths
