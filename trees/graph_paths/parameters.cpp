#include "trees/graph_paths/parameters.h"

#include "trees/graph_paths/poisson_disc.h"

#include <toml++/toml.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

#include "core/input_error.h"
#include "trees/toml_reader.h"

namespace landsim::trees::graph_paths {
namespace {

using Reader = TomlReader;

PrimitiveKind kind_of(const Reader& r, const toml::node& n) {
  const auto s = n.value<std::string>();
  if (s == "cylinder") return PrimitiveKind::cylinder;
  if (s == "cone") return PrimitiveKind::cone;
  if (s == "sphere") return PrimitiveKind::sphere;
  if (s == "sphere_portion") return PrimitiveKind::sphere_portion;
  if (s == "ellipsoid") return PrimitiveKind::ellipsoid;
  if (s == "revolution") return PrimitiveKind::revolution;
  r.refuse(n, "volume.kind", "cylinder, cone, sphere, sphere_portion, ellipsoid or revolution");
}

// [[height, radius], ...]: heights strictly increasing, radii 0-1000 m.
std::vector<ProfilePoint> read_profile(const Reader& r, const toml::node& n,
                                       const std::string& key) {
  const toml::array* a = n.as_array();
  const std::string expected =
      "[[height, radius], ...]: at least two points, heights strictly increasing, radii 0 to 1000";
  if (a == nullptr || a->size() < 2) r.refuse(n, key, expected);
  std::vector<ProfilePoint> profile;
  for (const toml::node& point : *a) {
    const toml::array* hr = point.as_array();
    if (hr == nullptr || hr->size() != 2) r.refuse(point, key, expected);
    const ProfilePoint p{r.number(*hr->get(0), key, -1e3, 1e3), r.number(*hr->get(1), key, 0, 1e3)};
    if (!profile.empty() && !(p.height > profile.back().height)) r.refuse(point, key, expected);
    profile.push_back(p);
  }
  return profile;
}

VolumePrimitive read_primitive(const Reader& r, const toml::table& t) {
  VolumePrimitive s;
  bool has_kind = false;
  r.read_table(t, "volume", "kind, origin, axis, radius, height, half_angle, radii, profile",
               [&](const std::string& k, const std::string& key, const toml::node& v) {
                 if (k == "kind")
                   s.kind = kind_of(r, v), has_kind = true;
                 else if (k == "origin")
                   s.origin = r.vector(v, key);
                 else if (k == "axis") {
                   s.axis = r.vector(v, key);
                   if (!(length(s.axis) > 1e-9)) r.refuse(v, key, "a direction, not [0, 0, 0]");
                   s.axis = normalize(s.axis);
                 } else if (k == "radius")
                   s.radius = r.number(v, key, 1e-3, 1e3);
                 else if (k == "height")
                   s.height = r.number(v, key, 1e-3, 1e3);
                 else if (k == "half_angle")
                   s.half_angle = r.number(v, key, 1, 180) * std::numbers::pi / 180;
                 else if (k == "radii") {
                   s.radii = r.vector(v, key);
                   if (!(std::min({s.radii.x, s.radii.y, s.radii.z}) >= 1e-3))
                     r.refuse(v, key, "three semi-axes, each at least 0.001 m");
                 } else if (k == "profile")
                   s.profile = read_profile(r, v, key);
                 else
                   return false;
                 return true;
               });
  if (!has_kind)
    r.refuse(t, "volume.kind", "a kind in every [[volume]]: cylinder, cone, sphere, ...");
  if (s.kind == PrimitiveKind::revolution && s.profile.size() < 2)
    r.refuse(t, "volume.profile",
             "[[height, radius], ...] with at least two points for a revolution");
  return s;
}

void read_graph(const Reader& r, const toml::table& t, Parameters& p) {
  r.read_table(t, "graph",
               "spacing, policy, cone_subdivisions, search_radius, threshold, weight_noise, root, "
               "endpoints, shell, endpoint_min_z",
               [&](const std::string& k, const std::string& key, const toml::node& v) {
                 if (k == "spacing")
                   p.spacing = r.number(v, key, 1e-3, 100);
                 else if (k == "policy") {
                   const auto s = v.value<std::string>();
                   if (s != "yao" && s != "threshold") r.refuse(v, key, "\"yao\" or \"threshold\"");
                   p.policy = s == "yao" ? GraphPolicy::yao : GraphPolicy::threshold;
                 } else if (k == "cone_subdivisions")
                   p.cone_subdivisions = r.integer(v, key, 3, 8);
                 else if (k == "search_radius")
                   p.search_radius = r.number(v, key, 1.5, 10);
                 else if (k == "threshold")
                   p.threshold = r.number(v, key, 1.0, 10);
                 else if (k == "weight_noise")
                   p.weight_noise = r.number(v, key, 0, 10);
                 else if (k == "root")
                   p.root = r.vector(v, key);
                 else if (k == "endpoints")
                   p.endpoints = r.integer(v, key, 1, 100000);
                 else if (k == "shell")
                   p.shell = r.number(v, key, 1e-3, 100);
                 else if (k == "endpoint_min_z")
                   p.endpoint_min_z = r.number(v, key, -1e4, 1e4);
                 else
                   return false;
                 return true;
               });
}

void read_thickness(const Reader& r, const toml::table& t, SkeletonOptions& o) {
  r.read_table(t, "thickness", "power, radius_scale, min_radius",
               [&](const std::string& k, const std::string& key, const toml::node& v) {
                 if (k == "power")
                   o.thickness_power = r.number(v, key, 0.1, 5);
                 else if (k == "radius_scale")
                   o.radius_scale = r.number(v, key, 1e-5, 10);
                 else if (k == "min_radius")
                   o.min_radius = r.number(v, key, 1e-4, 1);
                 else
                   return false;
                 return true;
               });
}

void read_leaves(const Reader& r, const toml::table& t, SkeletonOptions& o) {
  r.read_table(t, "leaves", "per_endpoint, length, width",
               [&](const std::string& k, const std::string& key, const toml::node& v) {
                 if (k == "per_endpoint")
                   o.leaves_per_endpoint = r.integer(v, key, 0, 64);
                 else if (k == "length")
                   o.leaf_length = r.number(v, key, 1e-3, 5);
                 else if (k == "width")
                   o.leaf_width = r.number(v, key, 1e-3, 5);
                 else
                   return false;
                 return true;
               });
}

void read_iteration(const Reader& r, const toml::table& t, IterationParameters& it) {
  constexpr double deg = std::numbers::pi / 180;
  r.read_table(t, "iteration",
               "levels, radius, size_ratio, half_angle, spacing_ratio, endpoints, shell, rotation, "
               "lifespan, terminate_probability, power, light, light_strength",
               [&](const std::string& k, const std::string& key, const toml::node& v) {
                 if (k == "levels")
                   it.levels = r.integer(v, key, 0, 6);
                 else if (k == "radius")
                   it.radius = r.number(v, key, 1e-3, 100);
                 else if (k == "size_ratio")
                   it.size_ratio = r.number(v, key, 0.05, 1);
                 else if (k == "half_angle")
                   it.half_angle = r.number(v, key, 5, 180) * deg;
                 else if (k == "spacing_ratio")
                   it.spacing_ratio = r.number(v, key, 0.05, 1);
                 else if (k == "endpoints")
                   it.endpoints = r.integer(v, key, 1, 64);
                 else if (k == "shell")
                   it.shell = r.number(v, key, 0.01, 1);
                 else if (k == "rotation")
                   it.rotation = r.number(v, key, -90, 90) * deg;
                 else if (k == "lifespan")
                   it.lifespan = r.number(v, key, 0, 20), it.use_lifespan = true;
                 else if (k == "terminate_probability")
                   it.terminate_probability = r.number(v, key, 0, 1);
                 else if (k == "power")
                   it.power = r.number(v, key, 0.1, 5);
                 else if (k == "light") {
                   it.light = r.vector(v, key);
                   if (!(length(it.light) > 1e-9)) r.refuse(v, key, "a direction, not [0, 0, 0]");
                 } else if (k == "light_strength")
                   it.light_strength = r.number(v, key, 0, 1);
                 else
                   return false;
                 return true;
               });
}

void read_refinement(const Reader& r, const toml::table& t, Parameters& p) {
  r.read_table(t, "refinement", "spheres, radius, cone_ratio, separation, junction",
               [&](const std::string& k, const std::string& key, const toml::node& v) {
                 if (k == "spheres")
                   p.refinement.spheres = r.integer(v, key, 0, 32);
                 else if (k == "radius")
                   p.refinement.radius = r.number(v, key, 0.01, 100);
                 else if (k == "cone_ratio")
                   p.refinement.cone_ratio = r.number(v, key, 0.05, 1);
                 else if (k == "separation")
                   p.refinement.separation = r.number(v, key, 0.5, 4);
                 else if (k == "junction")
                   p.junction = r.vector(v, key);
                 else
                   return false;
                 return true;
               });
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

double estimated_nodes(const Parameters& p) {
  double v = 0.0;
  for (const VolumePrimitive& s : p.volume.parts()) v += primitive_volume(s);
  // Refinement replaces the volume's fill by its spheres (and their thin cones).
  if (p.refinement.spheres > 0)
    v = p.refinement.spheres * 4.0 * std::numbers::pi * std::pow(p.refinement.radius, 3) / 3.0;
  double nodes = kNodesPerCubicSpacing * v / std::pow(p.spacing, 3);
  // Every endpoint of a level grows a subgraph at the next, each with the same node count
  // (radius and spacing shrink together); the light can raise endpoint counts by 1 + strength.
  const IterationParameters& it = p.iteration;
  VolumePrimitive sector;
  sector.kind = PrimitiveKind::sphere_portion;
  sector.radius = 1.0;
  sector.half_angle = it.half_angle;
  const double per_subgraph =
      kNodesPerCubicSpacing * primitive_volume(sector) / std::pow(it.spacing_ratio, 3);
  const double fan = it.endpoints * (1.0 + it.light_strength);
  double subgraphs = p.endpoints;
  for (int level = 1; level <= it.levels; ++level, subgraphs *= fan)
    nodes += subgraphs * per_subgraph;
  return nodes;
}

Parameters parse_parameters(std::string_view toml_text, const std::string& source) {
  const toml::table root = toml::parse(toml_text, source);  // species.cpp parsed it already
  const Reader r(source);
  Parameters p;
  std::vector<VolumePrimitive> parts;
  for (auto&& [k, v] : root) {
    if (k == "core" || k == "name" || k == "colours") continue;  // species.cpp's keys
    const std::string key(k.str());
    if (k == "graph")
      read_graph(r, r.table(v, key), p);
    else if (k == "thickness")
      read_thickness(r, r.table(v, key), p.skeleton);
    else if (k == "leaves")
      read_leaves(r, r.table(v, key), p.skeleton);
    else if (k == "iteration")
      read_iteration(r, r.table(v, key), p.iteration);
    else if (k == "refinement")
      read_refinement(r, r.table(v, key), p);
    else if (k == "volume")
      for (const toml::node& t : r.tables(v, key))
        parts.push_back(read_primitive(r, *t.as_table()));
    else
      r.refuse(v, key,
               "one of core, name, colours, [graph], [thickness], [leaves], [iteration], "
               "[refinement], [[volume]]");
  }
  if (parts.empty()) throw InputError(source + ": at least one [[volume]] is required");
  p.volume = InitialVolume(std::move(parts));
  if (const double n = estimated_nodes(p); n > static_cast<double>(p.max_nodes))
    throw InputError(source + ": graph.spacing " + std::to_string(p.spacing) + " and " +
                     std::to_string(p.iteration.levels) + " iteration.levels would make about " +
                     std::to_string(static_cast<long long>(n)) + " graph nodes (limit " +
                     std::to_string(p.max_nodes) +
                     "); raise graph.spacing or iteration.spacing_ratio, or lower "
                     "graph.endpoints, iteration.endpoints or iteration.levels");
  return p;
}

}  // namespace landsim::trees::graph_paths
