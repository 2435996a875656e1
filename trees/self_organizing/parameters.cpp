#include "trees/self_organizing/parameters.h"

#include <toml++/toml.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/input_error.h"
#include "trees/toml_reader.h"

namespace landsim::trees::self_organizing {
namespace {

constexpr double kDegree = std::numbers::pi / 180;
constexpr double kMaxMarkers = 5e6;  // markers one source may create: beyond, refused

using Reader = TomlReader;

void read_growth(const Reader& r, const toml::table& t, Parameters& p) {
  r.read_table(t, "growth", "steps, age, internode_length",
               [&](const std::string& k, const std::string& key, const toml::node& v) {
                 if (k == "steps" || k == "age")  // one step a year
                   p.steps = r.integer(v, key, 1, 500);
                 else if (k == "internode_length")
                   p.internode_length = r.number(v, key, 0.005, 2);
                 else
                   return false;
                 return true;
               });
}

void read_space(const Reader& r, const toml::table& t, SpaceParameters& s) {
  r.read_table(t, "space", "occupancy, perception, perception_angle, autonomous_markers",
               [&](const std::string& k, const std::string& key, const toml::node& v) {
                 if (k == "occupancy")
                   s.occupancy = r.number(v, key, 0.5, 10);
                 else if (k == "perception")
                   s.perception = r.number(v, key, 0.5, 20);
                 else if (k == "perception_angle")
                   s.perception_angle = r.number(v, key, 10, 360) * kDegree;
                 else if (k == "autonomous_markers")
                   s.autonomous_markers = r.integer(v, key, 0, 100);
                 else
                   return false;
                 return true;
               });
}

void read_light(const Reader& r, const toml::table& t, LightParameters& l) {
  r.read_table(t, "light", "full, a, b, depth, voxel, sensitivity",
               [&](const std::string& k, const std::string& key, const toml::node& v) {
                 if (k == "full")
                   l.full = r.number(v, key, 0.01, 100);
                 else if (k == "a")
                   l.a = r.number(v, key, 0, 100);
                 else if (k == "b")
                   l.b = r.number(v, key, 1.01, 100);
                 else if (k == "depth")
                   l.depth = r.integer(v, key, 0, 20);
                 else if (k == "voxel")
                   l.voxel = r.number(v, key, 0.25, 20);
                 else if (k == "sensitivity")
                   l.sensitivity = r.number(v, key, 0, 5);
                 else
                   return false;
                 return true;
               });
}

void read_vigour(const Reader& r, const toml::table& t, VigourParameters& g) {
  r.read_table(t, "vigour", "alpha, apical_control, shedding, max_shoot",
               [&](const std::string& k, const std::string& key, const toml::node& v) {
                 if (k == "alpha")
                   g.alpha = r.number(v, key, 0.01, 1000);
                 else if (k == "apical_control")
                   g.apical_control = r.number(v, key, 0, 1);
                 else if (k == "shedding")
                   g.shedding = r.number(v, key, 0, 1000);
                 else if (k == "max_shoot")
                   g.max_shoot = r.integer(v, key, 1, 20);
                 else
                   return false;
                 return true;
               });
}

void read_gravimorphism(const Reader& r, const toml::table& t, Gravimorphism& g) {
  r.read_table(t, "gravimorphism", "vertical, horizontal, offset",
               [&](const std::string& k, const std::string& key, const toml::node& v) {
                 if (k == "vertical")
                   g.vertical = r.number(v, key, 0.05, 20);
                 else if (k == "horizontal")
                   g.horizontal = r.number(v, key, 0.05, 20);
                 else if (k == "offset")
                   g.offset = r.number(v, key, -20, 20);
                 else
                   return false;
                 return true;
               });
  if (!(std::abs(g.offset) < g.vertical))
    r.refuse(t, "gravimorphism.offset",
             "an offset smaller than gravimorphism.vertical in size (the bud inside the "
             "ellipse), got " +
                 Reader::text(g.offset));
}

void read_direction(const Reader& r, const toml::table& t, DirectionParameters& d) {
  r.read_table(t, "direction",
               "heading, tropism, environment, set_point, trunk_set_point, branching, deflection, "
               "phyllotaxis, noise",
               [&](const std::string& k, const std::string& key, const toml::node& v) {
                 if (k == "heading")
                   d.heading = r.number(v, key, 0, 10);
                 else if (k == "tropism")
                   d.tropism = r.number(v, key, 0, 10);
                 else if (k == "environment")
                   d.environment = r.number(v, key, 0, 10);
                 else if (k == "set_point")
                   d.set_point = r.number(v, key, 0, 180) * kDegree;
                 else if (k == "trunk_set_point")
                   d.trunk_set_point = r.number(v, key, 0, 180) * kDegree;
                 else if (k == "branching")
                   d.branching = r.number(v, key, 0, 180) * kDegree;
                 else if (k == "deflection")
                   d.deflection = r.number(v, key, 0, 60) * kDegree;
                 else if (k == "phyllotaxis")
                   d.phyllotaxis = r.number(v, key, 0, 360) * kDegree;
                 else if (k == "noise")
                   d.noise = r.number(v, key, 0, 1);
                 else
                   return false;
                 return true;
               });
}

void read_width(const Reader& r, const toml::table& t, WidthParameters& w) {
  r.read_table(t, "width", "tip, exponent",
               [&](const std::string& k, const std::string& key, const toml::node& v) {
                 if (k == "tip")
                   w.tip = r.number(v, key, 1e-4, 0.5);
                 else if (k == "exponent")
                   w.exponent = r.number(v, key, 0.5, 20);
                 else
                   return false;
                 return true;
               });
}

WidthConstraint read_constraint(const Reader& r, const toml::table& t) {
  WidthConstraint c;
  r.read_table(t, "width_constraint", "internode, width",
               [&](const std::string& k, const std::string& key, const toml::node& v) {
                 if (k == "internode")
                   c.internode = static_cast<std::uint32_t>(r.integer(v, key, 0, 100000000));
                 else if (k == "width")
                   c.width = r.number(v, key, 1e-4, 10);
                 else
                   return false;
                 return true;
               });
  return c;
}

void read_leaves(const Reader& r, const toml::table& t, LeafParameters& l) {
  r.read_table(t, "leaves", "age, length, width",
               [&](const std::string& k, const std::string& key, const toml::node& v) {
                 if (k == "age")
                   l.age = r.integer(v, key, 0, 100);
                 else if (k == "length")
                   l.length = r.number(v, key, 1e-3, 2);
                 else if (k == "width")
                   l.width = r.number(v, key, 1e-3, 2);
                 else
                   return false;
                 return true;
               });
}

std::vector<std::array<double, 2>> read_silhouette(const Reader& r, const toml::node& n,
                                                   const std::string& key) {
  const std::string expected =
      "[[radius, height], ...]: at least three points of a closed outline, radii 0 to 100 m";
  const toml::array* a = n.as_array();
  if (a == nullptr || a->size() < 3) r.refuse(n, key, expected);
  std::vector<std::array<double, 2>> points;
  for (const toml::node& point : *a) {
    const toml::array* rz = point.as_array();
    if (rz == nullptr || rz->size() != 2) r.refuse(point, key, expected);
    points.push_back({r.number(*rz->get(0), key, 0, 100), r.number(*rz->get(1), key, -10, 200)});
  }
  return points;
}

void read_envelope(const Reader& r, const toml::table& t, Envelope& e) {
  e.kind = EnvelopeKind::silhouette;
  bool has_kind = false;
  r.read_table(t, "envelope", "kind, silhouette, centre, radii, density, confine",
               [&](const std::string& k, const std::string& key, const toml::node& v) {
                 if (k == "kind") {
                   const auto s = v.value<std::string>();
                   if (s != "silhouette" && s != "ellipsoid")
                     r.refuse(v, key, "\"silhouette\" or \"ellipsoid\"");
                   e.kind = s == "silhouette" ? EnvelopeKind::silhouette : EnvelopeKind::ellipsoid;
                   has_kind = true;
                 } else if (k == "silhouette")
                   e.silhouette = read_silhouette(r, v, key);
                 else if (k == "centre")
                   e.centre = r.vector(v, key);
                 else if (k == "radii") {
                   e.radii = r.vector(v, key);
                   if (!(std::min({e.radii.x, e.radii.y, e.radii.z}) >= 0.05))
                     r.refuse(v, key, "three semi-axes, each at least 0.05 m");
                 } else if (k == "density")
                   e.density = r.number(v, key, 0.1, 100000);
                 else if (k == "confine")
                   e.confine = r.boolean(v, key);
                 else
                   return false;
                 return true;
               });
  if (!has_kind) r.refuse(t, "envelope.kind", "\"silhouette\" or \"ellipsoid\"");
  if (e.kind == EnvelopeKind::silhouette && e.silhouette.size() < 3)
    r.refuse(t, "envelope.silhouette", "[[radius, height], ...] with at least three points");
  const auto [lo, hi] = e.bounds();
  const Vec3 size = hi - lo;
  if (e.density * size.x * size.y * size.z > kMaxMarkers)
    r.refuse(t, "envelope.density",
             "at most " + Reader::text(kMaxMarkers) + " markers over the envelope's bounds; got " +
                 Reader::text(e.density * size.x * size.y * size.z));
}

BrushStroke read_stroke(const Reader& r, const toml::table& t) {
  BrushStroke s;
  r.read_table(t, "stroke", "points, start_step, points_per_step, markers_per_step, max_age",
               [&](const std::string& k, const std::string& key, const toml::node& v) {
                 if (k == "points") {
                   const toml::array* a = v.as_array();
                   const std::string expected = "[[x, y, z, radius], ...] with at least one point";
                   if (a == nullptr || a->empty()) r.refuse(v, key, expected);
                   for (const toml::node& point : *a) {
                     const toml::array* q = point.as_array();
                     if (q == nullptr || q->size() != 4) r.refuse(point, key, expected);
                     s.points.push_back({{r.number(*q->get(0), key, -1e3, 1e3),
                                          r.number(*q->get(1), key, -1e3, 1e3),
                                          r.number(*q->get(2), key, -1e3, 1e3)},
                                         r.number(*q->get(3), key, 0.01, 100)});
                   }
                 } else if (k == "start_step")
                   s.start_step = r.integer(v, key, 1, 500);
                 else if (k == "points_per_step")
                   s.points_per_step = r.number(v, key, 0.01, 100);
                 else if (k == "markers_per_step")
                   s.markers_per_step = r.integer(v, key, 1, 100000);
                 else if (k == "max_age")
                   s.max_age = r.integer(v, key, 1, 500);
                 else
                   return false;
                 return true;
               });
  if (s.points.empty()) r.refuse(t, "stroke.points", "[[x, y, z, radius], ...]");
  return s;
}

Pruning read_prune(const Reader& r, const toml::table& t) {
  Pruning c;
  r.read_table(t, "prune", "step, internode",
               [&](const std::string& k, const std::string& key, const toml::node& v) {
                 if (k == "step")
                   c.step = r.integer(v, key, 1, 500);
                 else if (k == "internode")
                   c.internode = static_cast<std::uint32_t>(r.integer(v, key, 1, 100000000));
                 else
                   return false;
                 return true;
               });
  return c;
}

}  // namespace

Parameters parse_parameters(std::string_view toml_text, const std::string& source) {
  const toml::table root = toml::parse(toml_text, source);  // species.cpp parsed it already
  const Reader r(source);
  Parameters p;
  for (auto&& [k, v] : root) {
    if (k == "core" || k == "name" || k == "colours") continue;  // species.cpp's keys
    const std::string key(k.str());
    if (k == "growth")
      read_growth(r, r.table(v, key), p);
    else if (k == "space")
      read_space(r, r.table(v, key), p.space);
    else if (k == "light")
      read_light(r, r.table(v, key), p.light);
    else if (k == "vigour")
      read_vigour(r, r.table(v, key), p.vigour);
    else if (k == "gravimorphism")
      read_gravimorphism(r, r.table(v, key), p.gravimorphism);
    else if (k == "direction")
      read_direction(r, r.table(v, key), p.direction);
    else if (k == "width")
      read_width(r, r.table(v, key), p.width);
    else if (k == "leaves")
      read_leaves(r, r.table(v, key), p.leaves);
    else if (k == "envelope")
      read_envelope(r, r.table(v, key), p.envelope);
    else if (k == "width_constraint")
      for (const toml::node& t : r.tables(v, key))
        p.width.constraints.push_back(read_constraint(r, *t.as_table()));
    else if (k == "stroke")
      for (const toml::node& t : r.tables(v, key))
        p.strokes.push_back(read_stroke(r, *t.as_table()));
    else if (k == "prune")
      for (const toml::node& t : r.tables(v, key))
        p.prunings.push_back(read_prune(r, *t.as_table()));
    else
      r.refuse(v, key,
               "one of core, name, colours, [growth], [space], [light], [vigour], "
               "[gravimorphism], [direction], [width], [leaves], [envelope], "
               "[[width_constraint]], [[stroke]], [[prune]]");
  }
  if (p.envelope.kind == EnvelopeKind::none && p.strokes.empty() && p.space.autonomous_markers == 0)
    throw InputError(source +
                     ": no markers of free space: give an [envelope], a [[stroke]] or "
                     "space.autonomous_markers, or the tree cannot grow");
  return p;
}

}  // namespace landsim::trees::self_organizing
