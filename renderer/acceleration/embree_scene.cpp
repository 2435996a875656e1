#include "renderer/acceleration/embree_scene.h"

#include "renderer/acceleration/detail/embree_errors.h"
#include "renderer/acceleration/detail/prototype_levels.h"
#include "renderer/acceleration/stochastic_lod.h"
#include "renderer/camera.h"
#include "renderer/materials/grass_patch.h"
#include "renderer/transport/detail/ray_recorder.h"
#include "trees/degradation.h"

#include <embree3/rtcore.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <spdlog/spdlog.h>
#include <chrono>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <numbers>
#include <stdexcept>
#include <vector>

namespace landsim::renderer {
namespace {

// rtcSetNewGeometryBuffer, refusing to go on when Embree could not allocate (it returns
// null and reports the reason to EmbreeErrors).
void* new_geometry_buffer(RTCGeometry geom, RTCBufferType type, unsigned slot, RTCFormat format,
                          std::size_t stride, std::size_t count) {
  void* data = rtcSetNewGeometryBuffer(geom, type, slot, format, stride, count);
  if (data == nullptr && count > 0)
    throw std::runtime_error("Embree could not allocate a geometry buffer of " +
                             std::to_string(stride * count) + " bytes");
  return data;
}

// A triangle mesh with per-vertex normals (attribute 0), copied into Embree's own buffers
// (Embree pads them for its vector loads).
RTCGeometry make_mesh(RTCDevice device, const std::vector<Vec3f>& vertices,
                      const std::vector<Vec3f>& normals, const std::vector<std::uint32_t>& indices,
                      const std::vector<float>* uvs = nullptr) {
  RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
  auto* v = new_geometry_buffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, sizeof(Vec3f),
                                vertices.size());
  std::memcpy(v, vertices.data(), vertices.size() * sizeof(Vec3f));
  // Attribute 0: normals; attribute 1 (when given): texture coordinates.
  const bool with_uvs = uvs != nullptr && uvs->size() == 2 * vertices.size();
  rtcSetGeometryVertexAttributeCount(geom, with_uvs ? 2 : 1);
  auto* n = new_geometry_buffer(geom, RTC_BUFFER_TYPE_VERTEX_ATTRIBUTE, 0, RTC_FORMAT_FLOAT3,
                                sizeof(Vec3f), normals.size());
  std::memcpy(n, normals.data(), normals.size() * sizeof(Vec3f));
  if (with_uvs) {
    auto* t = new_geometry_buffer(geom, RTC_BUFFER_TYPE_VERTEX_ATTRIBUTE, 1, RTC_FORMAT_FLOAT2,
                                  2 * sizeof(float), vertices.size());
    std::memcpy(t, uvs->data(), uvs->size() * sizeof(float));
  }
  auto* i = new_geometry_buffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                3 * sizeof(std::uint32_t), indices.size() / 3);
  std::memcpy(i, indices.data(), indices.size() * sizeof(std::uint32_t));
  rtcCommitGeometry(geom);
  return geom;
}

RTCRay to_rtc(const Ray& ray, float t_near, float t_far, std::uint32_t mask = kAllBuckets) {
  RTCRay r{};
  r.org_x = ray.origin.x;
  r.org_y = ray.origin.y;
  r.org_z = ray.origin.z;
  r.dir_x = ray.direction.x;
  r.dir_y = ray.direction.y;
  r.dir_z = ray.direction.z;
  r.tnear = t_near;
  r.tfar = t_far;
  r.mask = mask;
  return r;
}

// Column-major 3x4: rotation about z by `angle`, uniform `scale`, the lean, then translation.
std::array<float, 12> instance_matrix(const TreeInstance& inst) {
  if (inst.leans()) {
    const double c = std::cos(inst.rotation) * inst.scale, s = std::sin(inst.rotation) * inst.scale;
    const Vec3 x = inst.apply_lean({c, s, 0.0}), y = inst.apply_lean({-s, c, 0.0}),
               z = inst.apply_lean({0.0, 0.0, inst.scale});
    return {static_cast<float>(x.x),
            static_cast<float>(x.y),
            static_cast<float>(x.z),
            static_cast<float>(y.x),
            static_cast<float>(y.y),
            static_cast<float>(y.z),
            static_cast<float>(z.x),
            static_cast<float>(z.y),
            static_cast<float>(z.z),
            static_cast<float>(inst.position.x),
            static_cast<float>(inst.position.y),
            static_cast<float>(inst.position.z)};
  }
  const auto c = static_cast<float>(std::cos(inst.rotation) * inst.scale);
  const auto s = static_cast<float>(std::sin(inst.rotation) * inst.scale);
  const auto k = static_cast<float>(inst.scale);
  return {c,
          s,
          0.0f,
          -s,
          c,
          0.0f,
          0.0f,
          0.0f,
          k,
          static_cast<float>(inst.position.x),
          static_cast<float>(inst.position.y),
          static_cast<float>(inst.position.z)};
}

Vec3f rotate_z(const Vec3f& v, double angle) {
  const auto c = static_cast<float>(std::cos(angle)), s = static_cast<float>(std::sin(angle));
  return {c * v.x - s * v.y, s * v.x + c * v.y, v.z};
}

// A triangle hit's vertex normal (attribute 0), turned by `rotation` about z; `fallback`
// where the interpolation degenerates.
Vec3f interpolated_normal(RTCGeometry geom, const RTCHit& hit, double rotation,
                          const Vec3f& fallback) {
  float n[3];
  rtcInterpolate0(geom, hit.primID, hit.u, hit.v, RTC_BUFFER_TYPE_VERTEX_ATTRIBUTE, 0, n, 3);
  const Vec3f shading = rotate_z(Vec3f{n[0], n[1], n[2]}, rotation);
  const float len = length(shading);
  return len > 0.0f ? shading / len : fallback;
}

// A triangle hit's texture coordinates (attribute 1) into `out`.
void texture_coordinates(RTCGeometry geom, const RTCHit& hit, Hit& out) {
  float uv[2];
  rtcInterpolate0(geom, hit.primID, hit.u, hit.v, RTC_BUFFER_TYPE_VERTEX_ATTRIBUTE, 1, uv, 2);
  out.u = uv[0];
  out.v = uv[1];
}

}  // namespace

// What a top-level geometry is: a tree instance at one level, a grass patch, a scene object
// or the ground.
struct TopLevelEntry {
  std::int32_t instance = -1;   // tree instance; for grass its frame (Impl::grass_frames); or -1
  std::int32_t level = -1;      // the prototype's level (PrototypeLevels index)
  std::uint8_t step = 0;        // the ladder step drawn (the lod AOV)
  std::uint8_t grass_type = 0;  // 1-3 for grass patches
  std::int32_t object = -1;     // scene object (Scene::objects), or -1
};

// A scene object's transform as Embree takes it (column-major 3 x 4, single precision).
std::array<float, 12> object_matrix(const ObjectInstance& o) {
  std::array<float, 12> m{};
  for (std::size_t k = 0; k < 12; ++k) m[k] = static_cast<float>(o.transform[k]);
  return m;
}

// A direction in an object's frame turned into the scene's, unit.
Vec3f object_to_scene(const ObjectInstance& o, const Vec3f& d) {
  return normalize(Vec3f(o.turn(Vec3(d))));
}

struct EmbreeScene::Impl {
  detail::EmbreeErrors errors;  // outlives the device (members are destroyed in reverse)
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
  std::vector<std::unique_ptr<detail::PrototypeLevels>> prototypes;
  std::vector<RTCScene> grass_patches;      // (type (0-2) x variant) x level
  std::vector<RTCScene> object_prototypes;  // one per Scene::object_prototypes
  // Each tree's lean as a rotation's columns, found once (empty when no tree leans).
  std::vector<std::array<Vec3f, 3>> leans;

  // A direction of tree `index`'s frame, turned about z already, turned by its lean.
  Vec3f leaned(std::int32_t index, const Vec3f& v) const {
    if (leans.empty()) return v;
    const std::array<Vec3f, 3>& m = leans[static_cast<std::size_t>(index)];
    return m[0] * v.x + m[1] * v.y + m[2] * v.z;
  }
  std::vector<TopLevelEntry> top;  // by top-level geometry ID
  const Scene* source = nullptr;
  // What a grass patch's filter needs: its blades' roots, its type, where its instances are.
  struct GrassFilter {
    const Impl* impl = nullptr;
    int type = 0;
    std::vector<float> roots;  // x, y per blade, patch space
  };
  std::vector<std::unique_ptr<GrassFilter>> grass_filters;
  std::vector<std::array<float, 12>> grass_frames;

  // Embree's filter for grass curves: a blade whose root the grass mask does not grant is
  // not there (no blades on roads or water; field edges at the map's own resolution).
  static void grass_filter(const RTCFilterFunctionNArguments* args) {
    const auto* f = static_cast<const GrassFilter*>(args->geometryUserPtr);
    for (unsigned i = 0; i < args->N; ++i) {
      if (args->valid[i] == 0) continue;
      const TopLevelEntry& e = f->impl->top[RTCHitN_instID(args->hit, args->N, i, 0)];
      const std::array<float, 12>& m = f->impl->grass_frames[static_cast<std::size_t>(e.instance)];
      const std::size_t blade = RTCHitN_primID(args->hit, args->N, i) / kSegmentsPerBlade;
      const float rx = f->roots[2 * blade], ry = f->roots[2 * blade + 1];
      const double x = m[0] * rx + m[3] * ry + m[9], y = m[1] * rx + m[4] * ry + m[10];
      if (!grass_blade_kept(f->impl->source->grass.mask, f->type, x, y)) args->valid[i] = 0;
    }
  }

  ~Impl() {
    prototypes.clear();
    for (RTCScene s : grass_patches)
      if (s) rtcReleaseScene(s);
    for (RTCScene s : object_prototypes)
      if (s) rtcReleaseScene(s);
    if (scene) rtcReleaseScene(scene);
    if (device) rtcReleaseDevice(device);
  }

  // An Embree instance of `instanced`, committed but not attached: trees make theirs on
  // every core, then attach them in order (attach_made).
  RTCGeometry make_instance(RTCScene instanced, const std::array<float, 12>& m,
                            std::uint32_t mask) const {
    RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_INSTANCE);
    rtcSetGeometryInstancedScene(geom, instanced);
    rtcSetGeometryTransform(geom, 0, RTC_FORMAT_FLOAT3X4_COLUMN_MAJOR, m.data());
    rtcSetGeometryMask(geom, mask);
    rtcCommitGeometry(geom);
    return geom;
  }

  unsigned attach_made(RTCGeometry geom, const TopLevelEntry& entry) {
    const unsigned id = rtcAttachGeometry(scene, geom);
    rtcReleaseGeometry(geom);
    if (top.size() <= id) top.resize(id + 1);
    top[id] = entry;
    return id;
  }

  unsigned attach_instance(RTCScene instanced, const std::array<float, 12>& m, std::uint32_t mask,
                           const TopLevelEntry& entry) {
    return attach_made(make_instance(instanced, m, mask), entry);
  }

  // Each patch twice: as it is, and with the blade filter for tiles the mask cuts (a filter
  // slows Embree's traversal, so whole tiles go without).
  static std::size_t patch_index(int type, int variant, int level, bool filtered) {
    return static_cast<std::size_t>(((type * kGrassVariants + variant) * kGrassLevels + level) * 2 +
                                    (filtered ? 1 : 0));
  }

  void add_grass_patches(const GrassCover& cover) {
    grass_patches.assign(3 * kGrassVariants * kGrassLevels * 2, nullptr);
    for (int t = 0; t < 3; ++t)
      for (int variant = 0; variant < kGrassVariants; ++variant)
        for (int level = 0; level < kGrassLevels; ++level) {
          const GrassBlades blades =
              make_grass_patch(cover.types[static_cast<std::size_t>(t)], cover.tile, level,
                               grass_patch_seed(t, variant));
          if (blades.first.empty()) continue;
          grass_patches[patch_index(t, variant, level, false)] = grass_patch_scene(blades, 0);
          if (!cover.mask.type.empty())
            grass_patches[patch_index(t, variant, level, true)] = grass_patch_scene(blades, t + 1);
        }
  }

  // A patch's blades as an Embree scene; with `filtered_type` (1-3) its blades are kept by
  // the grass mask (grass_filter).
  RTCScene grass_patch_scene(const GrassBlades& blades, int filtered_type) {
    RTCScene s = rtcNewScene(device);
    RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_ROUND_LINEAR_CURVE);
    auto* v = new_geometry_buffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4,
                                  4 * sizeof(float), blades.points.size() / 4);
    std::memcpy(v, blades.points.data(), blades.points.size() * sizeof(float));
    auto* i = new_geometry_buffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT,
                                  sizeof(std::uint32_t), blades.first.size());
    std::memcpy(i, blades.first.data(), blades.first.size() * sizeof(std::uint32_t));
    if (filtered_type != 0) {
      auto filter = std::make_unique<GrassFilter>();
      filter->impl = this;
      filter->type = filtered_type;
      for (std::size_t p = 0; p < blades.points.size(); p += 4 * (kSegmentsPerBlade + 1))
        filter->roots.insert(filter->roots.end(), {blades.points[p], blades.points[p + 1]});
      rtcSetGeometryUserData(geom, filter.get());
      rtcSetGeometryIntersectFilterFunction(geom, &Impl::grass_filter);
      rtcSetGeometryOccludedFilterFunction(geom, &Impl::grass_filter);
      grass_filters.push_back(std::move(filter));
    }
    rtcCommitGeometry(geom);
    rtcAttachGeometry(s, geom);
    rtcReleaseGeometry(geom);
    rtcCommitScene(s);
    return s;
  }

  // Patches within the grass range of `view`, at the levels their distance asks for (two
  // neighbouring levels with complementary ray masks where it falls between them).
  void add_grass(const GrassCover& cover, const View& view, bool blend) {
    if (cover.cols == 0) return;
    add_grass_patches(cover);
    for_each_grass_patch(cover, view, blend, [&](const GrassPatchPlacement& p) {
      const bool whole = grass_tile_whole(cover.mask, p.frame, cover.tile, p.type);
      RTCScene patch = grass_patches[patch_index(p.type - 1, p.variant, p.level, !whole)];
      if (patch == nullptr) return;
      TopLevelEntry entry;
      entry.grass_type = static_cast<std::uint8_t>(p.type);
      entry.instance = static_cast<std::int32_t>(grass_frames.size());
      grass_frames.push_back(p.frame);
      attach_instance(patch, p.frame, p.mask, entry);
    });
  }

  // Every prototype at the levels its instances need for `view` (all at full detail without
  // a view or with degradation off); returns where each instance is drawn.
  std::vector<detail::LevelBlend> build_prototypes(const Scene& s, const View* view) {
    const bool degrade = view != nullptr && s.settings.degradation;
    prototypes.resize(s.prototypes.size());
    tbb::parallel_for(std::size_t{0}, s.prototypes.size(), [&](std::size_t k) {
      prototypes[k] = std::make_unique<detail::PrototypeLevels>(device, s.prototypes[k], degrade);
    });
    // Each prototype's bounds: its range is measured to their middle height.
    std::vector<std::array<Vec3f, 2>> bounds(s.prototypes.size());
    if (degrade)
      tbb::parallel_for(std::size_t{0}, s.prototypes.size(),
                        [&](std::size_t k) { bounds[k] = s.prototypes[k].geometry.bounds(); });
    std::vector<detail::LevelBlend> blends(s.instances.size());
    for (std::size_t i = 0; i < s.instances.size(); ++i) {
      const TreeInstance& inst = s.instances[i];
      detail::LevelBlend& b = blends[i];
      if (!degrade) {
        b = prototypes.at(inst.prototype)->blend_for(0.0);
        continue;
      }
      const InstanceView at = instance_view(inst, bounds[inst.prototype], *view);
      // Small trees take one level each; without blending (benchmarks), the lower one.
      const bool per_pixel = at.pixels >= kPerPixelBlendMinPixels;
      std::optional<std::uint64_t> one_level;
      if (!per_pixel && s.settings.degradation_blend) one_level = static_cast<std::uint64_t>(i);
      b = prototypes.at(inst.prototype)->blend_for(at.r2, one_level);
      if (!s.settings.degradation_blend) {
        b.upper_level = b.lower_level;
        b.upper_step = b.lower_step;
        b.upper_weight = 0.0;
      }
    }
    tbb::parallel_for(std::size_t{0}, prototypes.size(),
                      [&](std::size_t k) { prototypes[k]->build(); });
    return blends;
  }

  // How an instance stands in the view: its calibrated range (to the middle of its height,
  // as scaled by the view's detail_range_scale) and its size on screen in pixels.
  struct InstanceView {
    double r2 = 0.0;
    double pixels = 0.0;
  };
  static InstanceView instance_view(const TreeInstance& inst, const std::array<Vec3f, 2>& b,
                                    const View& view) {
    const Vec3 centre = inst.position + Vec3(0.0, 0.0, 0.5 * (b[0].z + b[1].z) * inst.scale);
    const double distance = std::max(length(centre - view.position), 1e-6);
    const double size = std::max({b[1].x - b[0].x, b[1].y - b[0].y, b[1].z - b[0].z}) * inst.scale;
    return {view.detail_range_scale * calibrated_view_range(view, distance),
            pixels_across(view, size, distance)};
  }

  // Every object prototype once as a scene of its own (mesh normals as attribute 0, texture
  // coordinates as 1), and every object as an instance of it, seen by every ray.
  void add_objects(const Scene& s) {
    for (const ObjectPrototype& p : s.object_prototypes) {
      RTCScene proto = rtcNewScene(device);
      RTCGeometry mesh = make_mesh(device, p.vertices, p.normals, p.indices, &p.uvs);
      rtcAttachGeometry(proto, mesh);
      rtcReleaseGeometry(mesh);
      rtcCommitScene(proto);
      object_prototypes.push_back(proto);
    }
    for (std::size_t i = 0; i < s.objects.size(); ++i) {
      TopLevelEntry entry;
      entry.object = static_cast<std::int32_t>(i);
      attach_instance(object_prototypes.at(s.objects[i].prototype), object_matrix(s.objects[i]),
                      kAllBuckets, entry);
    }
  }

  // A hit on scene object `object`: its normals turned into the scene frame, its texture
  // coordinates.
  Hit object_hit(const RTCRayHit& rh, std::int32_t object, Hit hit) const {
    const ObjectInstance& o = source->objects[static_cast<std::size_t>(object)];
    hit.object = ObjectClass::object;
    hit.object_index = object;
    hit.geometric_normal = object_to_scene(o, Vec3f{rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z});
    RTCGeometry mesh = rtcGetGeometry(object_prototypes[o.prototype], rh.hit.geomID);
    float n[3];
    rtcInterpolate0(mesh, rh.hit.primID, rh.hit.u, rh.hit.v, RTC_BUFFER_TYPE_VERTEX_ATTRIBUTE, 0, n,
                    3);
    const Vec3f shading{n[0], n[1], n[2]};
    hit.shading_normal =
        length(shading) > 0.0f ? object_to_scene(o, shading) : hit.geometric_normal;
    if (!source->object_prototypes[o.prototype].uvs.empty()) texture_coordinates(mesh, rh.hit, hit);
    return hit;
  }

  // A tree's one or two Embree instances (the levels it blends), not yet attached.
  struct MadeInstances {
    std::array<RTCGeometry, 2> geom{nullptr, nullptr};
    std::array<TopLevelEntry, 2> entry{};
  };

  MadeInstances make_tree(const TreeInstance& inst, std::int32_t index,
                          const detail::LevelBlend& b) const {
    const detail::PrototypeLevels& levels = *prototypes.at(inst.prototype);
    const std::array<float, 12> m = instance_matrix(inst);
    const LevelMasks masks = level_masks(b.upper_weight, static_cast<std::uint64_t>(index));
    MadeInstances made;
    std::size_t k = 0;
    if (masks.lower != 0) {
      made.geom[k] = make_instance(levels.level(b.lower_level).scene, m, masks.lower);
      made.entry[k++] = {index, b.lower_level, static_cast<std::uint8_t>(b.lower_step), 0};
    }
    if (masks.upper != 0) {
      made.geom[k] = make_instance(levels.level(b.upper_level).scene, m, masks.upper);
      made.entry[k++] = {index, b.upper_level, static_cast<std::uint8_t>(b.upper_step), 0};
    }
    return made;
  }

  // Every tree's instances: made in parallel a chunk at a time (creating ten million Embree
  // geometries was half the BVH time of the ten-million-tree scene, on one core), attached
  // in the trees' order, so that the geometry IDs, and with them the BVH and the image, are
  // the serial loop's.
  void add_trees(const std::vector<TreeInstance>& instances,
                 const std::vector<detail::LevelBlend>& blends) {
    constexpr std::size_t kChunk = 1 << 16;
    top.reserve(top.size() + instances.size() + instances.size() / 8);
    std::vector<MadeInstances> made;
    for (std::size_t first = 0; first < instances.size(); first += kChunk) {
      const std::size_t n = std::min(kChunk, instances.size() - first);
      made.assign(n, MadeInstances{});
      tbb::parallel_for(
          tbb::blocked_range<std::size_t>(0, n), [&](const tbb::blocked_range<std::size_t>& r) {
            for (std::size_t i = r.begin(); i != r.end(); ++i) {
              const std::size_t t = first + i;
              made[i] = make_tree(instances[t], static_cast<std::int32_t>(t), blends[t]);
            }
          });
      for (const MadeInstances& m : made)
        for (std::size_t k = 0; k < 2; ++k)
          if (m.geom[k] != nullptr) attach_made(m.geom[k], m.entry[k]);
    }
  }
};

EmbreeScene::EmbreeScene(const Scene& scene, const View* view, Contents contents)
    : impl_(std::make_unique<Impl>()) {
  impl_->source = &scene;
  impl_->device = rtcNewDevice(nullptr);
  if (impl_->device == nullptr)
    throw std::runtime_error("Embree failed while creating its device: " +
                             detail::embree_error_name(rtcGetDeviceError(nullptr)));
  impl_->errors.watch(impl_->device);
  impl_->scene = rtcNewScene(impl_->device);
  if (contents == Contents::objects_only) {
    impl_->add_objects(scene);
    impl_->errors.check("adding the scene objects");
    rtcCommitScene(impl_->scene);
    impl_->errors.check("building the object scene");
    return;
  }
  if (scene.ground.mesh.triangle_count() > 0) {
    RTCGeometry ground = make_mesh(impl_->device, scene.ground.mesh.vertices,
                                   scene.ground.mesh.normals, scene.ground.mesh.indices);
    const unsigned id = rtcAttachGeometry(impl_->scene, ground);
    rtcReleaseGeometry(ground);
    impl_->top.resize(id + 1);
  }
  const std::vector<detail::LevelBlend> blends = impl_->build_prototypes(scene, view);
  if (std::any_of(scene.instances.begin(), scene.instances.end(),
                  [](const TreeInstance& t) { return t.leans(); })) {
    impl_->leans.reserve(scene.instances.size());
    for (const TreeInstance& t : scene.instances)
      impl_->leans.push_back({Vec3f(t.apply_lean({1, 0, 0})), Vec3f(t.apply_lean({0, 1, 0})),
                              Vec3f(t.apply_lean({0, 0, 1}))});
  }
  impl_->errors.check("building the tree prototypes");
  impl_->add_trees(scene.instances, blends);
  impl_->add_objects(scene);
  if (view != nullptr) impl_->add_grass(scene.grass, *view, scene.settings.degradation);
  impl_->errors.check("adding the instances, objects and grass patches");
  rtcCommitScene(impl_->scene);
  impl_->errors.check("building the instance scene");
}

EmbreeScene::~EmbreeScene() = default;

void EmbreeScene::record(const Ray& ray, float t_far, std::uint32_t mask, bool occlusion) const {
  const int index = tbb::this_task_arena::current_thread_index();
  (*recorder_)[static_cast<std::size_t>(std::max(index, 0))].push_back(
      {ray, t_far, mask, occlusion});
}

// Defined here, where the Embree scene is visible (the recorder's other members are in
// detail/ray_recorder.cpp).
double detail::RayRecorder::trace_raw(const EmbreeScene& scene,
                                      const std::vector<RecordedRay>& rays, int threads) {
  tbb::task_arena arena(threads);
  const auto start = std::chrono::steady_clock::now();
  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, rays.size(), 1024),
                      [&](const tbb::blocked_range<std::size_t>& r) {
                        RTCIntersectContext context;
                        rtcInitIntersectContext(&context);
                        for (std::size_t i = r.begin(); i != r.end(); ++i) {
                          if (rays[i].occlusion) {
                            RTCRay ray = to_rtc(rays[i].ray, 0.0f, rays[i].t_far, rays[i].mask);
                            rtcOccluded1(scene.impl_->scene, &context, &ray);
                          } else {
                            RTCRayHit rh{};
                            rh.ray = to_rtc(rays[i].ray, 0.0f, rays[i].t_far, rays[i].mask);
                            rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
                            rtcIntersect1(scene.impl_->scene, &context, &rh);
                          }
                        }
                      });
  });
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::optional<Hit> EmbreeScene::intersect(const Ray& ray, float t_near, float t_far,
                                          std::uint32_t mask) const {
  if (recorder_ != nullptr) record(ray, t_far, mask, false);
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit rh{};
  rh.ray = to_rtc(ray, t_near, t_far, mask);
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(impl_->scene, &context, &rh);
  if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return std::nullopt;

  Hit hit;
  hit.t = rh.ray.tfar;
  hit.primitive = rh.hit.primID;
  const Vec3f ng{rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z};
  if (rh.hit.instID[0] == RTC_INVALID_GEOMETRY_ID) {
    hit.object = ObjectClass::ground;
    hit.geometric_normal = normalize(ng);
    hit.shading_normal = interpolated_normal(rtcGetGeometry(impl_->scene, rh.hit.geomID), rh.hit,
                                             0.0, hit.geometric_normal);
    return hit;
  }
  const TopLevelEntry& entry = impl_->top[rh.hit.instID[0]];
  if (entry.object >= 0) return impl_->object_hit(rh, entry.object, hit);
  if (entry.grass_type != 0) {
    // Grass: Embree's curve normal is in the patch's space; the patch is tilted only
    // slightly, so the object-space normal serves for shading.
    hit.object = ObjectClass::grass;
    hit.grass_type = entry.grass_type;
    hit.geometric_normal = normalize(ng);
    hit.shading_normal = hit.geometric_normal;
    return hit;
  }
  hit.instance = entry.instance;
  hit.level = entry.step;
  const TreeInstance& inst = impl_->source->instances[static_cast<std::size_t>(hit.instance)];
  hit.prototype = static_cast<std::int32_t>(inst.prototype);
  const detail::PrototypeLevel& level = impl_->prototypes[inst.prototype]->level(entry.level);
  const detail::LevelGeometry& info = level.geometries[rh.hit.geomID];
  hit.object = info.group == trees::Group::leaves ? ObjectClass::leaf : ObjectClass::bark;
  hit.primitive = info.first + rh.hit.primID;
  hit.far_primitive = info.kind != detail::PrimitiveKind::triangles;
  // Instanced hits report normals in the prototype's space: turn them into the world's
  // (the instance transform is a rotation about z and a uniform scale).
  hit.geometric_normal = normalize(impl_->leaned(hit.instance, rotate_z(ng, inst.rotation)));
  if (hit.far_primitive) {
    hit.shading_normal = hit.geometric_normal;  // lines and discs: their own normal
    return hit;
  }
  RTCGeometry owner = rtcGetGeometry(level.scene, rh.hit.geomID);
  hit.shading_normal = impl_->leaned(
      hit.instance, interpolated_normal(owner, rh.hit, inst.rotation, hit.geometric_normal));
  if (hit.object == ObjectClass::bark && impl_->source->prototypes[inst.prototype].bark_texture)
    texture_coordinates(owner, rh.hit, hit);
  return hit;
}

bool EmbreeScene::occluded(const Ray& ray, float t_near, float t_far, std::uint32_t mask) const {
  if (recorder_ != nullptr) record(ray, t_far, mask, true);
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRay r = to_rtc(ray, t_near, t_far, mask);
  rtcOccluded1(impl_->scene, &context, &r);
  return r.tfar < 0.0f;  // Embree sets tfar to -inf on a hit
}

}  // namespace landsim::renderer
