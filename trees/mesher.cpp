#include "trees/mesher.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace landsim::trees {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;
constexpr double kApexRadius = 1e-6;  // below this a cross-section is a single point

// One cross-section's ring. The first vertex is repeated at the end (u = 1) so that bark
// textures wrap without a seam; `v` is the texture coordinate along the stem.
void add_ring(const CrossSection& s, int points, const StemSkeleton& stem, float v,
              TriangleSet& out) {
  const Vec3 y_axis = cross(s.axis, s.x_axis);
  if (s.radius <= kApexRadius) {
    out.vertices.push_back(Vec3f(s.position));
    out.normals.push_back(Vec3f(s.axis));
    out.uvs.insert(out.uvs.end(), {0.5f, v});
    return;
  }
  for (int j = 0; j <= points; ++j) {
    const double a = kTwoPi * j / points;
    double r = s.radius;
    if (stem.lobes > 0) r *= 1.0 + stem.lobe_depth * std::cos(stem.lobes * a);
    const Vec3 radial = s.x_axis * std::cos(a) + y_axis * std::sin(a);
    out.vertices.push_back(Vec3f(s.position + radial * r));
    out.normals.push_back(Vec3f(radial));
    out.uvs.insert(out.uvs.end(), {static_cast<float>(j) / static_cast<float>(points), v});
  }
}

// Joins ring `a` (first vertex ia, na vertices) to ring `b`; a ring of one vertex is an apex.
void join_rings(std::uint32_t ia, int na, std::uint32_t ib, int nb,
                std::vector<std::uint32_t>& idx) {
  if (na == 1 && nb == 1) return;
  // Rings repeat their first vertex at the end: n - 1 quads, no wrap-around.
  const int n = std::max(na, nb);
  for (int j = 0; j + 1 < n; ++j) {
    const auto j0 = static_cast<std::uint32_t>(j);
    const auto j1 = static_cast<std::uint32_t>(j + 1);
    const std::uint32_t a0 = na == 1 ? ia : ia + j0, a1 = na == 1 ? ia : ia + j1;
    const std::uint32_t b0 = nb == 1 ? ib : ib + j0, b1 = nb == 1 ? ib : ib + j1;
    if (na != 1) idx.insert(idx.end(), {a0, a1, b1});
    if (nb != 1) idx.insert(idx.end(), {a0, b1, b0});
  }
}

// Items given in generation order, as pointers in their stored (mass-rank-major) order.
template <typename Item>
std::vector<const Item*> stored_order(const std::vector<const Item*>& items, int mass_size) {
  std::vector<const Item*> stored(items.size());
  for (std::size_t i = 0; i < items.size(); ++i)
    stored[rank_major_position(i, items.size(), mass_size)] = items[i];
  return stored;
}

// One stem segment (the paper's item for stems): the band between two consecutive
// cross-sections and the line joining them. Rings are shared by the segments on either side,
// so vertices stay in stem order; only triangles and lines are stored rank-major.
struct Segment {
  std::uint32_t ring_a, ring_b;  // first vertex of each ring
  int count_a, count_b;          // vertices in each ring (1 at an apex)
  std::uint32_t line_first;      // first point of the line segment
};

// Appends one stem's rings and line points to its group; lists its segments.
void mesh_stem(const StemSkeleton& stem, const MeshResolution& res, GroupGeometry& g,
               std::vector<Segment>& segments) {
  const auto point_base = static_cast<std::uint32_t>(g.lines.points.size());
  const int points = res.ring_points[static_cast<std::size_t>(std::min(stem.level, 3))];
  std::uint32_t prev_start = 0;
  int prev_count = 0;
  // v runs along the stem in units of its base circumference, so bark keeps its aspect.
  const double circumference = kTwoPi * std::max(stem.sections.front().radius, 1e-4);
  double along = 0.0;
  for (std::size_t i = 0; i < stem.sections.size(); ++i) {
    if (i > 0) along += length(stem.sections[i].position - stem.sections[i - 1].position);
    const auto start = static_cast<std::uint32_t>(g.triangles.vertices.size());
    add_ring(stem.sections[i], points, stem, static_cast<float>(along / circumference),
             g.triangles);
    const int count = static_cast<int>(g.triangles.vertices.size() - start);
    if (i > 0)
      segments.push_back(
          {prev_start, start, prev_count, count, point_base + static_cast<std::uint32_t>(i - 1)});
    prev_start = start;
    prev_count = count;
    g.lines.points.push_back(Vec3f(stem.sections[i].position));
    g.lines.radii.push_back(static_cast<float>(stem.sections[i].radius));
  }
}

// A stem group: rings and points in generation order, then every segment's triangles and
// line in rank-major order (masses of 16 consecutive segments, in generation order).
GroupGeometry assemble_stems(const std::vector<const StemSkeleton*>& stems,
                             const MeshResolution& res) {
  GroupGeometry group;
  group.mass_size = kStemMassSize;
  std::vector<Segment> segments;
  for (const StemSkeleton* stem : stems) mesh_stem(*stem, res, group, segments);
  group.item_count = segments.size();
  std::vector<const Segment*> in_order;
  in_order.reserve(segments.size());
  for (const Segment& s : segments) in_order.push_back(&s);
  group.item_triangle_end.reserve(segments.size());
  group.item_line_end.reserve(segments.size());
  group.item_point_end.assign(segments.size(), 0);
  for (const Segment* s : stored_order(in_order, kStemMassSize)) {
    join_rings(s->ring_a, s->count_a, s->ring_b, s->count_b, group.triangles.indices);
    group.lines.first.push_back(s->line_first);
    group.item_triangle_end.push_back(static_cast<std::uint32_t>(group.triangles.triangle_count()));
    group.item_line_end.push_back(static_cast<std::uint32_t>(group.lines.segment_count()));
  }
  return group;
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

// Appends one leaf's polygon and disc point to the leaf group.
void mesh_leaf(const LeafSkeleton& leaf, const LeafMesh& m, GroupGeometry& g) {
  const auto vertex_base = static_cast<std::uint32_t>(g.triangles.vertices.size());
  const Vec3 side = normalize(cross(leaf.direction, leaf.normal));
  const auto place = [&](const Vec3f& t) {
    return leaf.base + side * (t.x * leaf.width) + leaf.direction * (t.y * leaf.length) +
           leaf.normal * (t.z * leaf.width);
  };
  for (std::size_t i = 0; i < m.shape.vertices.size(); ++i) {
    g.triangles.vertices.push_back(Vec3f(place(m.shape.vertices[i])));
    const Vec3f& n = m.normals[i];
    g.triangles.uvs.insert(g.triangles.uvs.end(),
                           {m.shape.vertices[i].x + 0.5f, m.shape.vertices[i].y});
    g.triangles.normals.push_back(
        Vec3f(normalize(side * n.x + leaf.direction * n.y + leaf.normal * n.z)));
  }
  for (std::uint32_t i : m.shape.indices) g.triangles.indices.push_back(vertex_base + i);
  g.points.centres.push_back(Vec3f(leaf.base + leaf.direction * (0.5 * leaf.length)));
  // A disc of the blade's area, so a distant leaf covers what the polygon covered.
  const double area = m.shape.area * leaf.length * leaf.width;
  g.points.radii.push_back(static_cast<float>(std::sqrt(area / std::numbers::pi)));
  g.points.normals.push_back(Vec3f(leaf.normal));
}

// Meshes leaves (given in generation order) straight into rank-major storage, recording
// where each stored item ends.
template <typename Item, typename MeshOne>
GroupGeometry assemble(const std::vector<const Item*>& items, int mass_size, MeshOne mesh_one,
                       std::size_t vertices_per_item, std::size_t indices_per_item) {
  GroupGeometry group;
  // Known sizes (leaves) are reserved up front: growing 20,000-leaf arrays costs more than
  // meshing them.
  group.triangles.vertices.reserve(items.size() * vertices_per_item);
  group.triangles.normals.reserve(items.size() * vertices_per_item);
  group.triangles.uvs.reserve(2 * items.size() * vertices_per_item);
  group.triangles.indices.reserve(items.size() * indices_per_item);
  group.mass_size = mass_size;
  group.item_count = items.size();
  group.item_triangle_end.reserve(items.size());
  group.item_line_end.reserve(items.size());
  group.item_point_end.reserve(items.size());
  for (const Item* item : stored_order(items, mass_size)) {
    mesh_one(*item, group);
    group.item_triangle_end.push_back(static_cast<std::uint32_t>(group.triangles.triangle_count()));
    group.item_line_end.push_back(static_cast<std::uint32_t>(group.lines.segment_count()));
    group.item_point_end.push_back(static_cast<std::uint32_t>(group.points.point_count()));
  }
  return group;
}

// Each leaf's vigour at its stored position, if any leaf is below full vigour.
void store_leaf_vigour(const std::vector<LeafSkeleton>& leaves, GroupGeometry& group) {
  const bool all_full = std::all_of(leaves.begin(), leaves.end(),
                                    [](const LeafSkeleton& l) { return l.vigour >= 1.0f; });
  if (all_full) return;
  group.item_vigour.resize(leaves.size());
  for (std::size_t i = 0; i < leaves.size(); ++i)
    group.item_vigour[rank_major_position(i, leaves.size(), group.mass_size)] =
        quantize_vigour(leaves[i].vigour);
}

}  // namespace

Group stem_group(int level) { return static_cast<Group>(std::clamp(level, 0, 3)); }

TreeGeometry mesh_tree(const TreeSkeleton& skeleton, const MeshResolution& resolution) {
  std::array<std::vector<const StemSkeleton*>, 4> stems;
  for (const StemSkeleton& stem : skeleton.stems) {
    if (stem.sections.size() < 2) continue;
    stems[static_cast<std::size_t>(stem_group(stem.level))].push_back(&stem);
  }
  TreeGeometry geometry;
  for (std::size_t g = 0; g < stems.size(); ++g) {
    geometry.groups[g] = assemble_stems(stems[g], resolution);
  }
  const LeafMesh leaf_mesh = prepare_leaf(skeleton.leaf_shape);
  std::vector<const LeafSkeleton*> leaves;
  leaves.reserve(skeleton.leaves.size());
  for (const LeafSkeleton& leaf : skeleton.leaves) leaves.push_back(&leaf);
  GroupGeometry& leaf_group = geometry.group(Group::leaves);
  leaf_group = assemble(
      leaves, kLeafMassSize,
      [&](const LeafSkeleton& l, GroupGeometry& out) { mesh_leaf(l, leaf_mesh, out); },
      leaf_mesh.shape.vertices.size(), leaf_mesh.shape.indices.size());
  store_leaf_vigour(skeleton.leaves, leaf_group);
  geometry.colours = skeleton.colours;
  return geometry;
}

}  // namespace landsim::trees
