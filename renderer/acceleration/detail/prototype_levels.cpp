#include "renderer/acceleration/detail/prototype_levels.h"

#include "renderer/acceleration/level_ladder.h"

#include <algorithm>
#include <cstring>
#include <stdexcept>
#include <string>

namespace landsim::renderer::detail {
namespace {

// Embree reads vertex buffers with 16-byte loads: every buffer gets that much slack.
constexpr std::size_t kPadding = 16;

RTCBuffer new_buffer(RTCDevice device, std::size_t bytes) {
  RTCBuffer b = rtcNewBuffer(device, bytes + kPadding);
  // Embree reports the reason through the device's error callback (EmbreeErrors).
  if (b == nullptr)
    throw std::runtime_error("Embree could not allocate a buffer of " + std::to_string(bytes) +
                             " bytes");
  return b;
}

template <typename T>
RTCBuffer copy_buffer(RTCDevice device, const T* data, std::size_t count) {
  RTCBuffer b = new_buffer(device, count * sizeof(T));
  std::memcpy(rtcGetBufferData(b), data, count * sizeof(T));
  return b;
}

void release(RTCBuffer b) {
  if (b) rtcReleaseBuffer(b);
}

// The largest value among the first `count` entries, plus one (0 for none).
std::uint32_t past_largest(const std::vector<std::uint32_t>& v, std::size_t count) {
  const auto end = v.begin() + static_cast<std::ptrdiff_t>(std::min(count, v.size()));
  return v.begin() == end ? 0u : *std::max_element(v.begin(), end) + 1u;
}

// Interleaves points and radii (times `scale`) as Embree's FLOAT4 (x, y, z, r) curve and
// disc vertices, for points [first, end).
RTCBuffer float4_buffer(RTCDevice device, const std::vector<Vec3f>& points,
                        const std::vector<float>& radii, std::size_t first, std::size_t end,
                        float scale = 1.0f) {
  RTCBuffer b = new_buffer(device, (end - first) * 4 * sizeof(float));
  auto* out = static_cast<float*>(rtcGetBufferData(b));
  for (std::size_t i = first; i < end; ++i, out += 4) {
    out[0] = points[i].x;
    out[1] = points[i].y;
    out[2] = points[i].z;
    out[3] = radii[i] * scale;
  }
  return b;
}

}  // namespace

PrototypeLevels::PrototypeLevels(RTCDevice device, const TreePrototype& prototype, bool degradation)
    : device_(device), prototype_(&prototype), degradation_(degradation) {
  step_level_.fill(-1);
  if (!degradation) return;  // every instance is drawn at full detail: no anchors to find
  anchor_ = anchor_steps(prototype);
}

LevelBlend PrototypeLevels::blend_for(double r2, std::optional<std::uint64_t> one_level_key) {
  if (!degradation_) {
    const int full = level_for_step(0);
    return {full, full, 0, 0, 0.0};
  }
  const LadderPosition at = ladder_position(r2);
  int lower = at.step, upper = at.step + 1;
  while (lower > 0 && !anchor_[static_cast<std::size_t>(lower)]) --lower;
  while (upper < kDetailSteps && !anchor_[static_cast<std::size_t>(upper)]) ++upper;
  double weight = 0.0;
  if (upper < kDetailSteps) {
    const double lo = step_r2(lower), hi = step_r2(upper);
    weight = std::round(std::clamp((r2 - lo) / (hi - lo), 0.0, 1.0) * kMaskBuckets) / kMaskBuckets;
  }
  // Equal details (past the last change, for instance) need no second level.
  if (weight > 0.0 && weight < 1.0 && detail_for_step(lower) == detail_for_step(upper))
    weight = 0.0;
  // One level for the whole object: the upper one for `weight` of objects.
  if (one_level_key && weight > 0.0 && weight < 1.0)
    weight = object_takes_upper(weight, *one_level_key) ? 1.0 : 0.0;
  if (weight >= 1.0) lower = upper;
  if (weight <= 0.0 || weight >= 1.0) {
    const int level = level_for_step(lower);
    return {level, level, lower, lower, 0.0};
  }
  return {level_for_step(lower), level_for_step(upper), lower, upper, weight};
}

PrototypeLevels::~PrototypeLevels() {
  for (PrototypeLevel& level : levels_)
    if (level.scene) rtcReleaseScene(level.scene);
}

const trees::TreeDetail& PrototypeLevels::detail_for_step(int step) {
  std::optional<trees::TreeDetail>& d = step_detail_[static_cast<std::size_t>(step)];
  if (!d) d = step_detail(*prototype_, degradation_ ? step : 0);
  return *d;
}

int PrototypeLevels::level_for_step(int step) {
  step = std::clamp(step, 0, kDetailSteps - 1);
  int& level = step_level_[static_cast<std::size_t>(step)];
  if (level >= 0) return level;
  const trees::TreeDetail& detail = detail_for_step(step);
  const auto found = std::find(details_.begin(), details_.end(), detail);
  level = static_cast<int>(found - details_.begin());
  if (found == details_.end()) details_.push_back(detail);
  return level;
}

// Each group's buffers, holding the prefix the most detailed requested level reaches.
PrototypeLevels::Buffers PrototypeLevels::make_buffers() const {
  Buffers buffers;
  for (int k = 0; k < trees::kGroupCount; ++k) {
    const auto index = static_cast<std::size_t>(k);
    const trees::GroupGeometry& g = prototype_->geometry.groups[index];
    GroupBuffers& b = buffers[index];
    std::uint32_t triangles = 0, far_end = 0;
    for (const trees::TreeDetail& d : details_) {
      const DrawnGroup n = drawn_group(g, static_cast<trees::Group>(k), d.groups[index]);
      triangles = std::max(triangles, n.triangles);
      far_end = std::max(far_end, n.far_end);
    }
    if (triangles > 0) {
      const std::vector<std::uint32_t>& idx = g.triangles.indices;
      b.vertex_count = past_largest(idx, 3u * triangles);
      b.vertices = copy_buffer(device_, g.triangles.vertices.data(), b.vertex_count);
      b.normals = copy_buffer(device_, g.triangles.normals.data(), b.vertex_count);
      if (g.triangles.uvs.size() == 2 * g.triangles.vertices.size())
        b.uvs = copy_buffer(device_, g.triangles.uvs.data(), 2u * b.vertex_count);
      b.indices = copy_buffer(device_, idx.data(), 3u * triangles);
    }
    if (far_end == 0) continue;
    if (static_cast<trees::Group>(k) == trees::Group::leaves) {
      b.far_vertex_count = far_end;
      b.far_vertices = float4_buffer(device_, g.points.centres, g.points.radii, 0, far_end);
      b.far_normals = copy_buffer(device_, g.points.normals.data(), far_end);
    } else {
      // A line joins points first[i] and first[i] + 1.
      b.far_vertex_count = past_largest(g.lines.first, far_end) + 1u;
      b.far_vertices = float4_buffer(device_, g.lines.points, g.lines.radii, 0, b.far_vertex_count);
      b.far_indices = copy_buffer(device_, g.lines.first.data(), far_end);
    }
  }
  return buffers;
}

void PrototypeLevels::build() {
  Buffers buffers = make_buffers();
  levels_.resize(details_.size());
  for (std::size_t i = 0; i < details_.size(); ++i) build_level(buffers, details_[i], levels_[i]);
  // The geometries hold their own references.
  for (GroupBuffers& b : buffers) {
    for (RTCBuffer r :
         {b.vertices, b.normals, b.uvs, b.indices, b.far_vertices, b.far_normals, b.far_indices})
      release(r);
  }
}

namespace {

unsigned attach(RTCScene scene, RTCGeometry geom) {
  rtcCommitGeometry(geom);
  const unsigned id = rtcAttachGeometry(scene, geom);
  rtcReleaseGeometry(geom);
  return id;
}

}  // namespace

void PrototypeLevels::build_level(const Buffers& buffers, const trees::TreeDetail& detail,
                                  PrototypeLevel& out) const {
  out.scene = rtcNewScene(device_);
  const auto record = [&](unsigned id, LevelGeometry info) {
    if (out.geometries.size() <= id) out.geometries.resize(id + 1);
    out.geometries[id] = info;
  };
  for (int k = 0; k < trees::kGroupCount; ++k) {
    const auto index = static_cast<std::size_t>(k);
    const auto group = static_cast<trees::Group>(k);
    const trees::GroupGeometry& g = prototype_->geometry.groups[index];
    const trees::GroupDetail& d = detail.groups[index];
    const DrawnGroup n = drawn_group(g, group, d);
    const GroupBuffers& b = buffers[index];
    if (n.triangles > 0) {
      RTCGeometry geom = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
      rtcSetGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, b.vertices, 0,
                           sizeof(Vec3f), b.vertex_count);
      // Attribute 0: normals; attribute 1 (when present): texture coordinates.
      rtcSetGeometryVertexAttributeCount(geom, b.uvs ? 2 : 1);
      rtcSetGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX_ATTRIBUTE, 0, RTC_FORMAT_FLOAT3, b.normals,
                           0, sizeof(Vec3f), b.vertex_count);
      if (b.uvs)
        rtcSetGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX_ATTRIBUTE, 1, RTC_FORMAT_FLOAT2, b.uvs, 0,
                             2 * sizeof(float), b.vertex_count);
      rtcSetGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, b.indices, 0,
                           3 * sizeof(std::uint32_t), n.triangles);
      record(attach(out.scene, geom), {group, PrimitiveKind::triangles, 0});
    }
    const std::uint32_t far_count = n.far_end - n.far_first;
    if (far_count == 0) continue;
    if (group == trees::Group::leaves) {
      // Discs of the blade's area, facing the blade's normal; widened ones (thinned far
      // leaves) are this level's own copy of the points it draws.
      RTCBuffer widened = d.far_scale == 1.0f
                              ? nullptr
                              : float4_buffer(device_, g.points.centres, g.points.radii,
                                              n.far_first, n.far_end, d.far_scale);
      RTCGeometry geom = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_ORIENTED_DISC_POINT);
      rtcSetGeometryBuffer(
          geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4, widened ? widened : b.far_vertices,
          widened ? 0 : n.far_first * 4 * sizeof(float), 4 * sizeof(float), far_count);
      release(widened);
      rtcSetGeometryBuffer(geom, RTC_BUFFER_TYPE_NORMAL, 0, RTC_FORMAT_FLOAT3, b.far_normals,
                           n.far_first * sizeof(Vec3f), sizeof(Vec3f), far_count);
      record(attach(out.scene, geom), {group, PrimitiveKind::discs, n.far_first});
    } else {
      // Stem segments as round lines of the stem's radius (widened when thinned).
      RTCBuffer widened = d.far_scale == 1.0f
                              ? nullptr
                              : float4_buffer(device_, g.lines.points, g.lines.radii, 0,
                                              b.far_vertex_count, d.far_scale);
      RTCGeometry geom = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_ROUND_LINEAR_CURVE);
      rtcSetGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4,
                           widened ? widened : b.far_vertices, 0, 4 * sizeof(float),
                           b.far_vertex_count);
      release(widened);
      rtcSetGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT, b.far_indices,
                           n.far_first * sizeof(std::uint32_t), sizeof(std::uint32_t), far_count);
      record(attach(out.scene, geom), {group, PrimitiveKind::lines, n.far_first});
    }
  }
  rtcCommitScene(out.scene);
}

}  // namespace landsim::renderer::detail
