#include "trees/self_organizing/parameters.h"

#include <toml++/toml.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/input_error.h"
#include "params/table_reader.h"

namespace landsim::trees::self_organizing {
namespace {

constexpr double kMaxMarkers = 5e6;  // markers one source may create: beyond, refused

using params::Range;
using params::TableReader;

void read_growth(TableReader r, Parameters& p) {
  // One step a year: `age` is the same key under the name a grower would use.
  const char* steps = r.has("age") ? "age" : "steps";
  p.steps = static_cast<int>(r.integer(steps, 1, 500, p.steps));
  p.internode_length = r.number("internode_length", {0.005, 2}, p.internode_length);
  r.finish();
}

void read_space(TableReader r, SpaceParameters& s) {
  s.occupancy = r.number("occupancy", {0.5, 10}, s.occupancy);
  s.perception = r.number("perception", {0.5, 20}, s.perception);
  s.perception_angle = r.angle("perception_angle", {10, 360}, s.perception_angle);
  s.autonomous_markers =
      static_cast<int>(r.integer("autonomous_markers", 0, 100, s.autonomous_markers));
  r.finish();
}

void read_light(TableReader r, LightParameters& l) {
  l.full = r.number("full", {0.01, 100}, l.full);
  l.a = r.number("a", {0, 100}, l.a);
  l.b = r.number("b", {1.01, 100}, l.b);
  l.depth = static_cast<int>(r.integer("depth", 0, 20, l.depth));
  l.voxel = r.number("voxel", {0.25, 20}, l.voxel);
  l.sensitivity = r.number("sensitivity", {0, 5}, l.sensitivity);
  r.finish();
}

void read_vigour(TableReader r, VigourParameters& g) {
  g.alpha = r.number("alpha", {0.01, 1000}, g.alpha);
  g.apical_control = r.number("apical_control", {0, 1}, g.apical_control);
  g.shedding = r.number("shedding", {0, 1000}, g.shedding);
  g.max_shoot = static_cast<int>(r.integer("max_shoot", 1, 20, g.max_shoot));
  r.finish();
}

void read_gravimorphism(TableReader r, Gravimorphism& g) {
  g.vertical = r.number("vertical", {0.05, 20}, g.vertical);
  g.horizontal = r.number("horizontal", {0.05, 20}, g.horizontal);
  g.offset = r.number("offset", {-20, 20}, g.offset);
  if (!(std::abs(g.offset) < g.vertical))
    r.fail("offset",
           "expected an offset smaller than vertical in size (the bud inside the "
           "ellipse), got " +
               params::format_number(g.offset));
  r.finish();
}

void read_direction(TableReader r, DirectionParameters& d) {
  d.heading = r.number("heading", {0, 10}, d.heading);
  d.tropism = r.number("tropism", {0, 10}, d.tropism);
  d.environment = r.number("environment", {0, 10}, d.environment);
  d.set_point = r.angle("set_point", {0, 180}, d.set_point);
  d.trunk_set_point = r.angle("trunk_set_point", {0, 180}, d.trunk_set_point);
  d.branching = r.angle("branching", {0, 180}, d.branching);
  d.deflection = r.angle("deflection", {0, 60}, d.deflection);
  d.phyllotaxis = r.angle("phyllotaxis", {0, 360}, d.phyllotaxis);
  d.noise = r.number("noise", {0, 1}, d.noise);
  r.finish();
}

void read_width(TableReader r, WidthParameters& w) {
  w.tip = r.number("tip", {1e-4, 0.5}, w.tip);
  w.exponent = r.number("exponent", {0.5, 20}, w.exponent);
  r.finish();
}

WidthConstraint read_constraint(TableReader r) {
  WidthConstraint c;
  c.internode = static_cast<std::uint32_t>(r.integer("internode", 0, 100000000, c.internode));
  c.width = r.number("width", {1e-4, 10}, c.width);
  r.finish();
  return c;
}

void read_leaves(TableReader r, LeafParameters& l) {
  l.age = static_cast<int>(r.integer("age", 0, 100, l.age));
  l.length = r.number("length", {1e-3, 2}, l.length);
  l.width = r.number("width", {1e-3, 2}, l.width);
  r.finish();
}

// Rows of `columns` numbers, each column in its range: silhouettes, stroke points.
std::vector<std::vector<double>> read_rows(TableReader& r, std::string_view key,
                                           const std::vector<Range>& columns, std::size_t min_rows,
                                           const std::string& expected) {
  std::vector<std::vector<double>> rows;
  const toml::node* n = r.value(key, expected);
  if (n == nullptr) return rows;
  const toml::array* a = n->as_array();
  if (a == nullptr || a->size() < min_rows) r.fail(key, "expected " + expected);
  for (const toml::node& point : *a) {
    const toml::array* q = point.as_array();
    if (q == nullptr || q->size() != columns.size()) r.fail_at(point, key, "expected " + expected);
    std::vector<double> row;
    for (std::size_t i = 0; i < columns.size(); ++i) {
      const auto v = q->get(i)->value<double>();
      if (!v || !columns[i].contains(*v))
        r.fail_at(*q->get(i), key,
                  "expected " + expected + "; column " + std::to_string(i + 1) + " " +
                      columns[i].describe());
      row.push_back(*v);
    }
    rows.push_back(std::move(row));
  }
  return rows;
}

void read_envelope(TableReader r, Envelope& e) {
  e.kind = r.choice("kind", {"silhouette", "ellipsoid"}) == "silhouette" ? EnvelopeKind::silhouette
                                                                         : EnvelopeKind::ellipsoid;
  for (const std::vector<double>& rz :
       read_rows(r, "silhouette", {{0, 100}, {-10, 200}}, 3,
                 "[[radius, height], ...]: at least three points of a closed outline, radii 0 "
                 "to 100 m"))
    e.silhouette.push_back({rz[0], rz[1]});
  e.centre = r.vec3("centre", {-1e4, 1e4}, e.centre);
  e.radii = r.vec3("radii", {0.05, 1e4}, e.radii);
  e.density = r.number("density", {0.1, 100000}, e.density);
  e.confine = r.boolean("confine", e.confine);
  if (e.kind == EnvelopeKind::silhouette && e.silhouette.size() < 3)
    r.fail("silhouette", "expected [[radius, height], ...] with at least three points");
  const auto [lo, hi] = e.bounds();
  const Vec3 size = hi - lo;
  if (e.density * size.x * size.y * size.z > kMaxMarkers)
    r.fail("density", "expected at most " + params::format_number(kMaxMarkers) +
                          " markers over the envelope's bounds; got " +
                          params::format_number(e.density * size.x * size.y * size.z));
  r.finish();
}

Lasso read_lasso(TableReader r) {
  LassoOutline o;
  for (const std::vector<double>& uv :
       read_rows(r, "outline", {{-100, 100}, {-10, 200}}, 3,
                 "[[across, height], ...]: at least three points of a closed outline in the "
                 "drawing plane, metres"))
    o.outline.push_back({uv[0], uv[1]});
  if (o.outline.size() < 3)
    r.fail("outline", "expected [[across, height], ...] with at least three points");
  o.origin = r.vec3("origin", {-1e3, 1e3}, o.origin);
  o.azimuth = r.angle("azimuth", {-360, 360}, o.azimuth);
  o.thickness = r.number("thickness", {0.05, 10}, o.thickness);
  o.density = r.number("density", {0.1, 100000}, o.density);
  o.start_step = static_cast<int>(r.integer("start_step", 1, 500, o.start_step));
  o.confine = r.boolean("confine", o.confine);
  Lasso lasso(std::move(o));
  const auto [lo, hi] = lasso.bounds();
  const Vec3 size = hi - lo;
  const double darts = lasso.outline().density * size.x * size.y * size.z;
  if (darts > kMaxMarkers)
    r.fail("density", "expected at most " + params::format_number(kMaxMarkers) +
                          " markers over the lasso's bounds; got " + params::format_number(darts));
  r.finish();
  return lasso;
}

// [[bend]]: base, and handles [[internode, x, y, z], ...] (the last one's internode is E).
Bend read_bend(TableReader r) {
  Bend b;
  constexpr Range kCoordinate{-1e3, 1e3};
  b.from = r.vec3("from", kCoordinate);
  for (const std::vector<double>& h :
       read_rows(r, "handles",
                 {kCoordinate, kCoordinate, kCoordinate, kCoordinate, kCoordinate, kCoordinate}, 1,
                 "[[x, y, z, to_x, to_y, to_z], ...] in metres: at least one handle, each a point "
                 "near an internode's tip and where that tip goes, the last the end"))
    b.handles.push_back({{h[0], h[1], h[2]}, {h[3], h[4], h[5]}});
  b.stretch = r.number("stretch", {0, 1}, b.stretch);
  b.where = r.location(nullptr) + ": [[bend]]";
  r.finish();
  return b;
}

BrushStroke read_stroke(TableReader r) {
  BrushStroke s;
  constexpr Range kCoordinate{-1e3, 1e3};
  for (const std::vector<double>& q :
       read_rows(r, "points", {kCoordinate, kCoordinate, kCoordinate, {0.01, 100}}, 1,
                 "[[x, y, z, radius], ...] with at least one point"))
    s.points.push_back({{q[0], q[1], q[2]}, q[3]});
  if (s.points.empty()) r.fail("points", "expected [[x, y, z, radius], ...]");
  s.start_step = static_cast<int>(r.integer("start_step", 1, 500, s.start_step));
  s.points_per_step = r.number("points_per_step", {0.01, 100}, s.points_per_step);
  s.markers_per_step =
      static_cast<int>(r.integer("markers_per_step", 1, 100000, s.markers_per_step));
  s.max_age = static_cast<int>(r.integer("max_age", 1, 500, s.max_age));
  r.finish();
  return s;
}

Pruning read_prune(TableReader r) {
  Pruning c;
  c.step = static_cast<int>(r.integer("step", 1, 500, c.step));
  c.at = r.vec3("at", {-1e3, 1e3});
  c.stub = r.boolean("stub", c.stub);
  c.where = r.location(nullptr) + ": [[prune]]";
  r.finish();
  return c;
}

// A [[phase]]: the rules before it (`before`) with the tables it gives changed.
GrowthPhase read_phase(TableReader r, const GrowthPhase& before) {
  GrowthPhase ph = before;
  ph.selective = false;
  ph.from_step = static_cast<int>(r.integer("from_step", 1, 500));  // order: the caller
  read_vigour(r.table("vigour"), ph.vigour);
  read_gravimorphism(r.table("gravimorphism"), ph.gravimorphism);
  read_direction(r.table("direction"), ph.direction);
  if (r.has("select")) {
    ph.selective = true;
    ph.select = r.vec3("select");
  }
  r.finish();
  return ph;
}

}  // namespace

bool Parameters::confined_out(const Vec3& p, int step) const {
  bool confined = false;
  if (envelope.kind != EnvelopeKind::none && envelope.confine) {
    if (envelope.contains(p)) return false;
    confined = true;
  }
  for (const Lasso& lasso : lassos) {
    if (!lasso.outline().confine || lasso.outline().start_step > step) continue;
    if (lasso.contains(p)) return false;
    confined = true;
  }
  return confined;
}

Parameters read_parameters(params::TableReader& root, const std::string& source) {
  Parameters p;
  p.source = source;
  read_growth(root.table("growth"), p);
  read_space(root.table("space"), p.space);
  read_light(root.table("light"), p.light);
  read_vigour(root.table("vigour"), p.vigour);
  read_gravimorphism(root.table("gravimorphism"), p.gravimorphism);
  read_direction(root.table("direction"), p.direction);
  read_width(root.table("width"), p.width);
  read_leaves(root.table("leaves"), p.leaves);
  if (root.has("envelope")) read_envelope(root.table("envelope"), p.envelope);
  for (TableReader& t : root.tables("width_constraint"))
    p.width.constraints.push_back(read_constraint(t));
  for (TableReader& t : root.tables("lasso")) p.lassos.push_back(read_lasso(t));
  // The strokes' markers alive at once, at most: each drops markers_per_step a step while
  // its brush moves, each living max_age steps. Beyond the growth's marker limit the species
  // is refused here, at the stroke, before anything grows.
  double stroke_markers = 0.0;
  for (TableReader& t : root.tables("stroke")) {
    p.strokes.push_back(read_stroke(t));
    const BrushStroke& s = p.strokes.back();
    const double moving =
        std::min(std::floor(static_cast<double>(s.points.size() - 1) / s.points_per_step) + 1.0,
                 static_cast<double>(std::max(p.steps - s.start_step + 1, 0)));
    stroke_markers += s.markers_per_step * std::min(static_cast<double>(s.max_age), moving);
    if (stroke_markers > static_cast<double>(p.max_markers))
      t.fail("markers_per_step",
             "the strokes would hold up to " + params::format_number(stroke_markers) +
                 " markers at once, more than the " + std::to_string(p.max_markers) +
                 " landsim grows with: lower markers_per_step or max_age");
  }
  for (TableReader& t : root.tables("bend")) p.bends.push_back(read_bend(t));
  for (TableReader& t : root.tables("prune")) p.prunings.push_back(read_prune(t));
  GrowthPhase rules{0, p.vigour, p.gravimorphism, p.direction, false, {}};
  for (TableReader& t : root.tables("phase")) {
    const int previous = rules.from_step;
    rules = read_phase(t, rules);
    if (rules.from_step <= previous)
      t.fail("from_step",
             "expected phases in order of from_step, each later than the one "
             "before (" +
                 std::to_string(previous) + ")");
    p.phases.push_back(rules);
  }
  if (p.envelope.kind == EnvelopeKind::none && p.lassos.empty() && p.strokes.empty() &&
      p.space.autonomous_markers == 0)
    throw InputError(source +
                     ": no markers of free space: give an [envelope], a [[lasso]], a [[stroke]] "
                     "or space.autonomous_markers, or the tree cannot grow");
  return p;
}

}  // namespace landsim::trees::self_organizing
