#include "trees/mesher.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace landsim::trees {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;
constexpr double kApexRadius = 1e-6;  // below this a cross-section is a single point

// Geometry of one item before it is placed in rank-major order.
struct ItemGeometry {
  TriangleSet triangles;
  LineSet lines;
  PointSet points;
};

void add_ring(const CrossSection& s, int points, const StemSkeleton& stem, TriangleSet& out) {
  const Vec3 y_axis = cross(s.axis, s.x_axis);
  if (s.radius <= kApexRadius) {
    out.vertices.push_back(Vec3f(s.position));
    out.normals.push_back(Vec3f(s.axis));
    return;
  }
  for (int j = 0; j < points; ++j) {
    const double a = kTwoPi * j / points;
    double r = s.radius;
    if (stem.lobes > 0) r *= 1.0 + stem.lobe_depth * std::cos(stem.lobes * a);
    const Vec3 radial = s.x_axis * std::cos(a) + y_axis * std::sin(a);
    out.vertices.push_back(Vec3f(s.position + radial * r));
    out.normals.push_back(Vec3f(radial));
  }
}

// Joins ring `a` (first vertex ia, na vertices) to ring `b`; a ring of one vertex is an apex.
void join_rings(std::uint32_t ia, int na, std::uint32_t ib, int nb,
                std::vector<std::uint32_t>& idx) {
  if (na == 1 && nb == 1) return;
  const int n = std::max(na, nb);
  for (int j = 0; j < n; ++j) {
    const auto j0 = static_cast<std::uint32_t>(j);
    const auto j1 = static_cast<std::uint32_t>((j + 1) % n);
    const std::uint32_t a0 = na == 1 ? ia : ia + j0, a1 = na == 1 ? ia : ia + j1;
    const std::uint32_t b0 = nb == 1 ? ib : ib + j0, b1 = nb == 1 ? ib : ib + j1;
    if (na != 1) idx.insert(idx.end(), {a0, a1, b1});
    if (nb != 1) idx.insert(idx.end(), {a0, b1, b0});
  }
}

ItemGeometry mesh_stem(const StemSkeleton& stem, const MeshResolution& res) {
  ItemGeometry g;
  const int points = res.ring_points[static_cast<std::size_t>(std::min(stem.level, 3))];
  std::uint32_t prev_start = 0;
  int prev_count = 0;
  for (std::size_t i = 0; i < stem.sections.size(); ++i) {
    const auto start = static_cast<std::uint32_t>(g.triangles.vertices.size());
    add_ring(stem.sections[i], points, stem, g.triangles);
    const int count = static_cast<int>(g.triangles.vertices.size() - start);
    if (i > 0) join_rings(prev_start, prev_count, start, count, g.triangles.indices);
    prev_start = start;
    prev_count = count;

    g.lines.points.push_back(Vec3f(stem.sections[i].position));
    g.lines.radii.push_back(static_cast<float>(stem.sections[i].radius));
    if (i > 0) g.lines.first.push_back(static_cast<std::uint32_t>(i - 1));
  }
  return g;
}

struct LeafMesh {
  LeafTemplate shape;
  std::vector<Vec3f> normals;  // per template vertex, unit, in the template frame
};

LeafMesh prepare_leaf(const LeafShape& shape) {
  LeafMesh m{make_leaf_template(shape), {}};
  m.normals.assign(m.shape.vertices.size(), Vec3f{});
  for (std::size_t i = 0; i + 2 < m.shape.indices.size(); i += 3) {
    const std::uint32_t a = m.shape.indices[i], b = m.shape.indices[i + 1],
                        c = m.shape.indices[i + 2];
    const Vec3f n =
        cross(m.shape.vertices[b] - m.shape.vertices[a], m.shape.vertices[c] - m.shape.vertices[a]);
    for (std::uint32_t v : {a, b, c}) m.normals[v] += n;
  }
  for (Vec3f& n : m.normals) n = length(n) > 0.0f ? normalize(n) : Vec3f{0.0f, 0.0f, 1.0f};
  return m;
}

ItemGeometry mesh_leaf(const LeafSkeleton& leaf, const LeafMesh& m) {
  ItemGeometry g;
  const Vec3 side = normalize(cross(leaf.direction, leaf.normal));
  const auto place = [&](const Vec3f& t) {
    return leaf.base + side * (t.x * leaf.width) + leaf.direction * (t.y * leaf.length) +
           leaf.normal * (t.z * leaf.width);
  };
  for (std::size_t i = 0; i < m.shape.vertices.size(); ++i) {
    g.triangles.vertices.push_back(Vec3f(place(m.shape.vertices[i])));
    const Vec3f& n = m.normals[i];
    g.triangles.normals.push_back(
        Vec3f(normalize(side * n.x + leaf.direction * n.y + leaf.normal * n.z)));
  }
  g.triangles.indices = m.shape.indices;
  g.points.centres.push_back(Vec3f(leaf.base + leaf.direction * (0.5 * leaf.length)));
  // A disc of the blade's area, so a distant leaf covers what the polygon covered.
  const double area = m.shape.area * leaf.length * leaf.width;
  g.points.radii.push_back(static_cast<float>(std::sqrt(area / std::numbers::pi)));
  g.points.normals.push_back(Vec3f(leaf.normal));
  return g;
}

void append(TriangleSet& to, const TriangleSet& from) {
  const auto offset = static_cast<std::uint32_t>(to.vertices.size());
  to.vertices.insert(to.vertices.end(), from.vertices.begin(), from.vertices.end());
  to.normals.insert(to.normals.end(), from.normals.begin(), from.normals.end());
  for (std::uint32_t i : from.indices) to.indices.push_back(offset + i);
}

void append(LineSet& to, const LineSet& from) {
  const auto offset = static_cast<std::uint32_t>(to.points.size());
  to.points.insert(to.points.end(), from.points.begin(), from.points.end());
  to.radii.insert(to.radii.end(), from.radii.begin(), from.radii.end());
  for (std::uint32_t i : from.first) to.first.push_back(offset + i);
}

void append(PointSet& to, const PointSet& from) {
  to.centres.insert(to.centres.end(), from.centres.begin(), from.centres.end());
  to.radii.insert(to.radii.end(), from.radii.begin(), from.radii.end());
  to.normals.insert(to.normals.end(), from.normals.begin(), from.normals.end());
}

// Stores items (given in generation order) rank-major, recording where each item ends.
GroupGeometry assemble(std::vector<ItemGeometry>& items, int mass_size) {
  GroupGeometry group;
  group.mass_size = mass_size;
  group.item_count = items.size();
  std::vector<const ItemGeometry*> stored(items.size());
  for (std::size_t i = 0; i < items.size(); ++i) {
    stored[rank_major_position(i, items.size(), mass_size)] = &items[i];
  }
  for (const ItemGeometry* item : stored) {
    append(group.triangles, item->triangles);
    append(group.lines, item->lines);
    append(group.points, item->points);
    group.item_triangle_end.push_back(static_cast<std::uint32_t>(group.triangles.triangle_count()));
    group.item_line_end.push_back(static_cast<std::uint32_t>(group.lines.segment_count()));
    group.item_point_end.push_back(static_cast<std::uint32_t>(group.points.point_count()));
  }
  return group;
}

}  // namespace

Group stem_group(int level) { return static_cast<Group>(std::clamp(level, 0, 3)); }

TreeGeometry mesh_tree(const TreeSkeleton& skeleton, const MeshResolution& resolution) {
  std::array<std::vector<ItemGeometry>, 4> stems;
  for (const StemSkeleton& stem : skeleton.stems) {
    if (stem.sections.size() < 2) continue;
    stems[static_cast<std::size_t>(stem_group(stem.level))].push_back(mesh_stem(stem, resolution));
  }
  TreeGeometry geometry;
  for (std::size_t g = 0; g < stems.size(); ++g)
    geometry.groups[g] = assemble(stems[g], kStemMassSize);

  const LeafMesh leaf_mesh = prepare_leaf(skeleton.leaf_shape);
  std::vector<ItemGeometry> leaves;
  leaves.reserve(skeleton.leaves.size());
  for (const LeafSkeleton& leaf : skeleton.leaves) leaves.push_back(mesh_leaf(leaf, leaf_mesh));
  geometry.group(Group::leaves) = assemble(leaves, kLeafMassSize);
  geometry.colours = skeleton.colours;
  return geometry;
}

}  // namespace landsim::trees
