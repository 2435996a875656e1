#include "trees/degradation.h"

#include <algorithm>
#include <cmath>

namespace landsim::trees {
namespace {

constexpr double kStemMass = kStemMassSize;
constexpr double kLeafMass = kLeafMassSize;

double bounded(double number, double mass_size) { return std::clamp(number, 0.0, mass_size); }

// Level 0 stems (the trunk). Lines below r2 = 100 are left out because they "can appear as
// seam"; polygons thin out between 300 and 800 and stop there.
MassNumbers trunk(double r2) {
  MassNumbers n;
  n.far = r2 < 100.0 ? 0.0 : kStemMass;
  if (r2 < 300.0) {
    n.polygons = kStemMass;
  } else if (r2 < 800.0) {
    n.polygons = bounded(kStemMass * (1.5 - r2 / 600.0), kStemMass);
  }
  return n;
}

// Level 1 stems (main branches).
MassNumbers level1(double r2, double s) {
  MassNumbers n;
  if (r2 < 200.0 * s) {
    n.polygons = bounded(kStemMass * (1.5 - r2 / 600.0), kStemMass);
    n.far = kStemMass;
  } else if (r2 < 2000.0 * s) {
    n.far = bounded(kStemMass * (2.2 - 1.2 * std::pow(r2 / (200.0 * s), 0.3)), kStemMass);
  }
  return n;
}

// Level 2 stems (other branches; level 3+ follows them).
MassNumbers level2(double r2, double s) {
  MassNumbers n;
  if (r2 < 50.0 * s) {
    n.polygons = kStemMass;
    n.far = kStemMass;
  } else if (r2 < 100.0 * s) {
    n.polygons = bounded(kStemMass * (2.0 - r2 / (50.0 * s)), kStemMass);
    n.far = kStemMass;
  } else if (r2 < 500.0 * s) {
    n.far = bounded(kStemMass * (2.0 - std::sqrt(r2 / (100.0 * s))), kStemMass);
  }
  return n;
}

// Leaves: polygons to d / 4, thinning to none at d; points from there on, never fewer than
// one per mass.
MassNumbers leaves(double r2, double d) {
  MassNumbers n;
  if (r2 < d / 4.0) {
    n.polygons = kLeafMass;
    n.far = kLeafMass;
  } else if (r2 < d) {
    n.polygons = bounded(kLeafMass * (4.0 / 3.0 - r2 / (3.0 * d / 4.0)), kLeafMass);
    n.far = kLeafMass;
  } else {
    n.far = std::clamp(kLeafMass * (1.5 - r2 / (2.0 * d)), 1.0, kLeafMass);
  }
  return n;
}

std::size_t mass_total(std::size_t total, int mass_size) {
  const auto size = static_cast<std::size_t>(mass_size);
  return (total + size - 1) / size;
}

// The paper's loop over masses, calling draw(index) for every item it draws.
template <typename Draw>
void paper_loop(std::size_t total, int mass_size, double number, Draw&& draw) {
  const auto size = static_cast<std::size_t>(mass_size);
  number = std::clamp(number, 0.0, static_cast<double>(mass_size));
  const double whole = std::floor(number);
  const auto int_number = static_cast<std::size_t>(whole);
  const std::size_t masses = mass_total(total, mass_size);
  const double change = static_cast<double>(masses) * (number - whole);
  for (std::size_t mass = 0; mass < masses; ++mass) {
    const std::size_t start = mass * size;
    std::size_t end = start + int_number;
    // `mass < change` as the paper writes it, with room for rounding (3.6 must give 0.6).
    if (static_cast<double>(mass) + 1e-9 < change) ++end;
    end = std::min({end, start + size, total});  // a short last mass has fewer items
    for (std::size_t index = start; index < end; ++index) draw(index);
  }
}

std::uint32_t far_in_prefix(const GroupGeometry& g, Group group, std::size_t items) {
  return group == Group::leaves ? g.points_in_prefix(items) : g.lines_in_prefix(items);
}

// How much wider the drawn lines or points are made so that the group keeps its area when
// only `drawn` of `items` are drawn as lines or points and none as polygons.
float far_widening(Group group, std::size_t items, std::size_t drawn, std::size_t polygons) {
  if (drawn == 0 || drawn >= items || polygons > 0) return 1.0f;
  const double ratio = static_cast<double>(items) / static_cast<double>(drawn);
  return static_cast<float>(group == Group::leaves ? std::sqrt(ratio)
                                                   : std::min(ratio, kMaxLineWidening));
}

}  // namespace

std::optional<Season> season_from_name(std::string_view name) {
  if (name == "spring") return Season::spring;
  if (name == "summer") return Season::summer;
  if (name == "autumn") return Season::autumn;
  if (name == "winter") return Season::winter;
  return std::nullopt;
}

DegradationFactors degradation_factors(double quality, Season season, bool evergreen) {
  DegradationFactors f;
  const bool leafy = evergreen || season == Season::summer || season == Season::autumn;
  f.s = leafy ? quality / 2.0 : quality;
  f.d = season == Season::spring ? 100.0 : 200.0;
  return f;
}

double calibrated_range(double range_m, int image_height, double fov_y_deg) {
  return range_m * 1000.0 / image_height * fov_y_deg / 60.0;
}

double range_for_calibrated(double r2, int image_height, double fov_y_deg) {
  return r2 * image_height / 1000.0 * 60.0 / fov_y_deg;
}

std::array<MassNumbers, kGroupCount> mass_numbers(double r2, const DegradationFactors& factors) {
  return {trunk(r2), level1(r2, factors.s), level2(r2, factors.s), level2(r2, factors.s),
          leaves(r2, factors.d)};
}

std::vector<std::size_t> paper_loop_items(std::size_t total, int mass_size, double number) {
  std::vector<std::size_t> items;
  paper_loop(total, mass_size, number, [&](std::size_t index) { items.push_back(index); });
  return items;
}

std::size_t drawn_item_count(std::size_t total, int mass_size, double number) {
  std::size_t count = 0;
  paper_loop(total, mass_size, number, [&](std::size_t) { ++count; });
  return count;
}

TreeDetail tree_detail(const TreeGeometry& geometry, double r2, const DegradationFactors& factors) {
  const std::array<MassNumbers, kGroupCount> numbers = mass_numbers(r2, factors);
  TreeDetail detail;
  for (int k = 0; k < kGroupCount; ++k) {
    const auto group = static_cast<Group>(k);
    const GroupGeometry& g = geometry.group(group);
    GroupDetail& out = detail.groups[static_cast<std::size_t>(k)];
    const MassNumbers& n = numbers[static_cast<std::size_t>(k)];
    out.polygon_items = drawn_item_count(g.item_count, g.mass_size, n.polygons);
    out.far_items = drawn_item_count(g.item_count, g.mass_size, n.far);
    out.triangles = g.triangles_in_prefix(out.polygon_items);
    out.far_primitives = far_in_prefix(g, group, out.far_items);
    out.far_only_first = far_in_prefix(g, group, std::min(out.polygon_items, out.far_items));
    out.far_only_end = out.far_primitives;
    out.far_scale = far_widening(group, g.item_count, out.far_items, out.polygon_items);
  }
  return detail;
}

TreeDetail full_detail(const TreeGeometry& geometry) {
  TreeDetail detail;
  for (int k = 0; k < kGroupCount; ++k) {
    const GroupGeometry& g = geometry.groups[static_cast<std::size_t>(k)];
    GroupDetail& out = detail.groups[static_cast<std::size_t>(k)];
    out.polygon_items = g.item_count;
    out.triangles = static_cast<std::uint32_t>(g.triangles.triangle_count());
  }
  return detail;
}

}  // namespace landsim::trees
