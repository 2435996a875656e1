#pragma once
// Private to renderer/ (includes Embree): one tree prototype inside Embree at the levels of
// range degradation its instances ask for. Every level is an Embree scene of its own, but
// all of them read the same Embree buffers (vertices, normals, indices, curve points, disc
// points), each level a prefix or a range of them: an extra level costs its BVH only.
// Buffers hold only the prefix that the most detailed level in use reaches, so a forest
// seen only from afar never copies its leaf polygons into Embree.
#include <embree3/rtcore.h>

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "renderer/acceleration/stochastic_lod.h"
#include "renderer/scene.h"
#include "trees/degradation.h"

namespace landsim::renderer::detail {

enum class PrimitiveKind : std::uint8_t { triangles, lines, discs };

// One Embree geometry of a level: which group, drawn as what; `first` is the stored index
// of its primitive 0 (lines and discs of a level are a range that need not start at 0).
struct LevelGeometry {
  trees::Group group = trees::Group::trunk;
  PrimitiveKind kind = PrimitiveKind::triangles;
  std::uint32_t first = 0;
};

struct PrototypeLevel {
  RTCScene scene = nullptr;
  std::vector<LevelGeometry> geometries;  // by geometry ID
};

// Where an instance is drawn: at the lower level, or (upper_weight of its pixels) at the
// upper one; steps are the ladder steps of the two levels (the lod AOV).
struct LevelBlend {
  int lower_level = 0, upper_level = 0;
  int lower_step = 0, upper_step = 0;
  double upper_weight = 0.0;  // a multiple of 1 / kMaskBuckets
};

class PrototypeLevels {
 public:
  PrototypeLevels(RTCDevice device, const TreePrototype& prototype, bool degradation);
  ~PrototypeLevels();
  PrototypeLevels(const PrototypeLevels&) = delete;
  PrototypeLevels& operator=(const PrototypeLevels&) = delete;

  // The levels an instance at calibrated range r2 is drawn with (asking for them). Only
  // anchor steps are drawn: a step whose leaves are partly polygons is skipped, and the
  // blend between the anchors around it draws the same expected share of leaf polygons
  // (the paper's share falls linearly in r2) with one leaf-polygon BVH instead of several;
  // where leaves are discs only, every other step (octaves) is an anchor.
  // Not thread-safe; call build() once every instance has asked.
  // With `one_level_key`, the object takes one of the two levels, by a hash of the key
  // (object_takes_upper), and only that level is built.
  LevelBlend blend_for(double r2, std::optional<std::uint64_t> one_level_key = std::nullopt);
  // The level drawn at ladder step `step` (equal details share one level).
  int level_for_step(int step);
  // Copies the buffers and builds every requested level's BVH.
  void build();
  const PrototypeLevel& level(int index) const { return levels_[static_cast<std::size_t>(index)]; }
  std::size_t level_count() const { return levels_.size(); }

 private:
  struct GroupBuffers {
    RTCBuffer vertices = nullptr, normals = nullptr, uvs = nullptr, indices = nullptr;
    std::uint32_t vertex_count = 0;
    RTCBuffer far_vertices = nullptr, far_normals = nullptr, far_indices = nullptr;
    std::uint32_t far_vertex_count = 0;
  };
  using Buffers = std::array<GroupBuffers, trees::kGroupCount>;
  Buffers make_buffers() const;
  const trees::TreeDetail& detail_for_step(int step);
  void build_level(const Buffers& buffers, const trees::TreeDetail& detail,
                   PrototypeLevel& out) const;

  RTCDevice device_;
  const TreePrototype* prototype_;
  bool degradation_;
  std::array<int, kDetailSteps> step_level_;
  std::array<bool, kDetailSteps> anchor_{};
  std::array<std::optional<trees::TreeDetail>, kDetailSteps> step_detail_;
  std::vector<trees::TreeDetail> details_;
  std::vector<PrototypeLevel> levels_;
};

}  // namespace landsim::renderer::detail
