#include "renderer/embree_scene.h"

#include "renderer/grass_patch.h"

#include <embree3/rtcore.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <spdlog/spdlog.h>
#include <chrono>

#include <array>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <vector>

namespace landsim::renderer {
namespace {

void report_embree_error(void*, RTCError code, const char* message) {
  spdlog::error("Embree error {}: {}", static_cast<int>(code), message ? message : "");
}

// A triangle mesh with per-vertex normals (attribute 0), copied into Embree's own buffers
// (Embree pads them for its vector loads).
RTCGeometry make_mesh(RTCDevice device, const std::vector<Vec3f>& vertices,
                      const std::vector<Vec3f>& normals, const std::vector<std::uint32_t>& indices,
                      const std::vector<float>* uvs = nullptr) {
  RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
  auto* v = rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                    sizeof(Vec3f), vertices.size());
  std::memcpy(v, vertices.data(), vertices.size() * sizeof(Vec3f));
  // Attribute 0: normals; attribute 1 (when given): texture coordinates.
  const bool with_uvs = uvs != nullptr && uvs->size() == 2 * vertices.size();
  rtcSetGeometryVertexAttributeCount(geom, with_uvs ? 2 : 1);
  auto* n = rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX_ATTRIBUTE, 0, RTC_FORMAT_FLOAT3,
                                    sizeof(Vec3f), normals.size());
  std::memcpy(n, normals.data(), normals.size() * sizeof(Vec3f));
  if (with_uvs) {
    auto* t = rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX_ATTRIBUTE, 1, RTC_FORMAT_FLOAT2,
                                      2 * sizeof(float), vertices.size());
    std::memcpy(t, uvs->data(), uvs->size() * sizeof(float));
  }
  auto* i = rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                    3 * sizeof(std::uint32_t), indices.size() / 3);
  std::memcpy(i, indices.data(), indices.size() * sizeof(std::uint32_t));
  rtcCommitGeometry(geom);
  return geom;
}

RTCRay to_rtc(const Ray& ray, float t_near, float t_far) {
  RTCRay r{};
  r.org_x = ray.origin.x;
  r.org_y = ray.origin.y;
  r.org_z = ray.origin.z;
  r.dir_x = ray.direction.x;
  r.dir_y = ray.direction.y;
  r.dir_z = ray.direction.z;
  r.tnear = t_near;
  r.tfar = t_far;
  r.mask = 0xffffffffu;
  return r;
}

// Column-major 3x4: rotation about z by `angle`, uniform `scale`, then translation.
std::array<float, 12> instance_matrix(const TreeInstance& inst) {
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

}  // namespace

struct EmbreeScene::Impl {
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
  std::vector<RTCScene> prototypes;
  std::vector<RTCScene> grass_patches;  // type (0-2) x level
  // Top-level geometry ID -> grass type (1-3) for grass instances, else 0.
  std::vector<std::uint8_t> grass_of;
  // For each prototype, the object class of each of its geometries (by geometry ID).
  std::vector<std::vector<ObjectClass>> prototype_classes;
  // Top-level geometry ID -> tree instance index (-1 for the ground).
  std::vector<std::int32_t> instance_of;
  const Scene* source = nullptr;

  ~Impl() {
    for (RTCScene s : prototypes) rtcReleaseScene(s);
    for (RTCScene s : grass_patches)
      if (s) rtcReleaseScene(s);
    if (scene) rtcReleaseScene(scene);
    if (device) rtcReleaseDevice(device);
  }

  void add_prototype(const TreePrototype& proto) {
    RTCScene s = rtcNewScene(device);
    std::vector<ObjectClass> classes;
    for (int g = 0; g < trees::kGroupCount; ++g) {
      const trees::TriangleSet& t = proto.geometry.groups[static_cast<std::size_t>(g)].triangles;
      if (t.indices.empty()) continue;
      RTCGeometry geom = make_mesh(device, t.vertices, t.normals, t.indices, &t.uvs);
      const unsigned id = rtcAttachGeometry(s, geom);
      rtcReleaseGeometry(geom);
      classes.resize(id + 1);
      classes[id] =
          g == static_cast<int>(trees::Group::leaves) ? ObjectClass::leaf : ObjectClass::bark;
    }
    rtcCommitScene(s);
    prototypes.push_back(s);
    prototype_classes.push_back(std::move(classes));
  }

  void add_grass_patches(const GrassCover& cover) {
    grass_patches.assign(3 * kGrassLevels, nullptr);
    for (int t = 0; t < 3; ++t) {
      for (int level = 0; level < kGrassLevels; ++level) {
        const GrassBlades blades = make_grass_patch(cover.types[static_cast<std::size_t>(t)],
                                                    cover.tile, level, grass_patch_seed(t));
        if (blades.first.empty()) continue;
        RTCScene s = rtcNewScene(device);
        RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_ROUND_LINEAR_CURVE);
        auto* v = rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4,
                                          4 * sizeof(float), blades.points.size() / 4);
        std::memcpy(v, blades.points.data(), blades.points.size() * sizeof(float));
        auto* i = rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT,
                                          sizeof(std::uint32_t), blades.first.size());
        std::memcpy(i, blades.first.data(), blades.first.size() * sizeof(std::uint32_t));
        rtcCommitGeometry(geom);
        rtcAttachGeometry(s, geom);
        rtcReleaseGeometry(geom);
        rtcCommitScene(s);
        grass_patches[static_cast<std::size_t>(t * kGrassLevels + level)] = s;
      }
    }
  }

  // Patches within the grass range of `view`, at the level its distance asks for.
  void add_grass(const GrassCover& cover, const View& view) {
    if (cover.cols == 0) return;
    add_grass_patches(cover);
    for_each_grass_patch(cover, view, [&](int type, int level, const std::array<float, 12>& m) {
      RTCScene patch = grass_patches[static_cast<std::size_t>((type - 1) * kGrassLevels + level)];
      if (patch == nullptr) return;
      RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_INSTANCE);
      rtcSetGeometryInstancedScene(geom, patch);
      rtcSetGeometryTransform(geom, 0, RTC_FORMAT_FLOAT3X4_COLUMN_MAJOR, m.data());
      rtcCommitGeometry(geom);
      const unsigned id = rtcAttachGeometry(scene, geom);
      rtcReleaseGeometry(geom);
      instance_of.resize(id + 1, -1);
      grass_of.resize(id + 1, 0);
      grass_of[id] = static_cast<std::uint8_t>(type);
    });
  }

  void add_instance(const TreeInstance& inst, std::int32_t index) {
    RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_INSTANCE);
    rtcSetGeometryInstancedScene(geom, prototypes.at(inst.prototype));
    const std::array<float, 12> m = instance_matrix(inst);
    rtcSetGeometryTransform(geom, 0, RTC_FORMAT_FLOAT3X4_COLUMN_MAJOR, m.data());
    rtcCommitGeometry(geom);
    const unsigned id = rtcAttachGeometry(scene, geom);
    rtcReleaseGeometry(geom);
    instance_of.resize(id + 1, -1);
    instance_of[id] = index;
  }
};

EmbreeScene::EmbreeScene(const Scene& scene, const View* view) : impl_(std::make_unique<Impl>()) {
  impl_->source = &scene;
  impl_->device = rtcNewDevice(nullptr);
  if (impl_->device == nullptr) throw std::runtime_error("Embree: could not create a device");
  rtcSetDeviceErrorFunction(impl_->device, report_embree_error, nullptr);
  impl_->scene = rtcNewScene(impl_->device);
  if (scene.ground.mesh.triangle_count() > 0) {
    RTCGeometry ground = make_mesh(impl_->device, scene.ground.mesh.vertices,
                                   scene.ground.mesh.normals, scene.ground.mesh.indices);
    const unsigned id = rtcAttachGeometry(impl_->scene, ground);
    rtcReleaseGeometry(ground);
    impl_->instance_of.resize(id + 1, -1);
  }
  for (const TreePrototype& p : scene.prototypes) impl_->add_prototype(p);
  for (std::size_t i = 0; i < scene.instances.size(); ++i) {
    impl_->add_instance(scene.instances[i], static_cast<std::int32_t>(i));
  }
  if (view != nullptr) impl_->add_grass(scene.grass, *view);
  impl_->grass_of.resize(impl_->instance_of.size(), 0);
  rtcCommitScene(impl_->scene);
}

EmbreeScene::~EmbreeScene() = default;

void EmbreeScene::record(const Ray& ray, float t_far, bool occlusion) const {
  const int index = tbb::this_task_arena::current_thread_index();
  (*recorder_)[static_cast<std::size_t>(std::max(index, 0))].push_back({ray, t_far, occlusion});
}

double EmbreeScene::trace_raw(const std::vector<RecordedRay>& rays, int threads) const {
  tbb::task_arena arena(threads);
  const auto start = std::chrono::steady_clock::now();
  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, rays.size(), 1024),
                      [&](const tbb::blocked_range<std::size_t>& r) {
                        RTCIntersectContext context;
                        rtcInitIntersectContext(&context);
                        for (std::size_t i = r.begin(); i != r.end(); ++i) {
                          if (rays[i].occlusion) {
                            RTCRay ray = to_rtc(rays[i].ray, 0.0f, rays[i].t_far);
                            rtcOccluded1(impl_->scene, &context, &ray);
                          } else {
                            RTCRayHit rh{};
                            rh.ray = to_rtc(rays[i].ray, 0.0f, rays[i].t_far);
                            rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
                            rtcIntersect1(impl_->scene, &context, &rh);
                          }
                        }
                      });
  });
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::optional<Hit> EmbreeScene::intersect(const Ray& ray, float t_near, float t_far) const {
  if (recorder_ != nullptr) record(ray, t_far, false);
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit rh{};
  rh.ray = to_rtc(ray, t_near, t_far);
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(impl_->scene, &context, &rh);
  if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return std::nullopt;

  Hit hit;
  hit.t = rh.ray.tfar;
  hit.primitive = rh.hit.primID;
  RTCScene owner = impl_->scene;
  double rotation = 0.0;
  if (rh.hit.instID[0] != RTC_INVALID_GEOMETRY_ID && impl_->grass_of[rh.hit.instID[0]] != 0) {
    // Grass: Embree's curve normal is in the patch's space; the patch is tilted only
    // slightly, so the object-space normal serves for shading.
    hit.object = ObjectClass::grass;
    hit.grass_type = impl_->grass_of[rh.hit.instID[0]];
    hit.geometric_normal = normalize(Vec3f{rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z});
    hit.shading_normal = hit.geometric_normal;
    return hit;
  }
  if (rh.hit.instID[0] != RTC_INVALID_GEOMETRY_ID) {
    hit.instance = impl_->instance_of[rh.hit.instID[0]];
    const TreeInstance& inst = impl_->source->instances[static_cast<std::size_t>(hit.instance)];
    hit.prototype = static_cast<std::int32_t>(inst.prototype);
    owner = impl_->prototypes[inst.prototype];
    hit.object = impl_->prototype_classes[inst.prototype][rh.hit.geomID];
    rotation = inst.rotation;
    if (hit.object == ObjectClass::bark && impl_->source->prototypes[inst.prototype].bark_texture) {
      float uv[2];
      rtcInterpolate0(rtcGetGeometry(owner, rh.hit.geomID), rh.hit.primID, rh.hit.u, rh.hit.v,
                      RTC_BUFFER_TYPE_VERTEX_ATTRIBUTE, 1, uv, 2);
      hit.u = uv[0];
      hit.v = uv[1];
    }
  } else {
    hit.object = ObjectClass::ground;
  }
  // Instanced hits report normals in the prototype's space: turn them into the world's
  // (the instance transform is a rotation about z and a uniform scale).
  hit.geometric_normal =
      normalize(rotate_z(Vec3f{rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z}, rotation));
  float n[3];
  rtcInterpolate0(rtcGetGeometry(owner, rh.hit.geomID), rh.hit.primID, rh.hit.u, rh.hit.v,
                  RTC_BUFFER_TYPE_VERTEX_ATTRIBUTE, 0, n, 3);
  const Vec3f shading = rotate_z(Vec3f{n[0], n[1], n[2]}, rotation);
  const float len = length(shading);
  hit.shading_normal = len > 0.0f ? shading / len : hit.geometric_normal;
  return hit;
}

bool EmbreeScene::occluded(const Ray& ray, float t_near, float t_far) const {
  if (recorder_ != nullptr) record(ray, t_far, true);
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRay r = to_rtc(ray, t_near, t_far);
  rtcOccluded1(impl_->scene, &context, &r);
  return r.tfar < 0.0f;  // Embree sets tfar to -inf on a hit
}

}  // namespace landsim::renderer
