#include "renderer/embree_scene.h"

#include <embree3/rtcore.h>
#include <spdlog/spdlog.h>

#include <cstring>
#include <limits>
#include <stdexcept>

namespace landsim::renderer {
namespace {

void report_embree_error(void*, RTCError code, const char* message) {
  spdlog::error("Embree error {}: {}", static_cast<int>(code), message ? message : "");
}

// Copies the ground mesh into a new Embree triangle geometry, vertex normals as attribute 0.
RTCGeometry make_ground(RTCDevice device, const terrain::GroundMesh& mesh) {
  RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
  auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
      geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, sizeof(Vec3f), mesh.vertices.size()));
  std::memcpy(vertices, mesh.vertices.data(), mesh.vertices.size() * sizeof(Vec3f));
  rtcSetGeometryVertexAttributeCount(geom, 1);
  auto* normals = static_cast<float*>(
      rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX_ATTRIBUTE, 0, RTC_FORMAT_FLOAT3,
                              sizeof(Vec3f), mesh.normals.size()));
  std::memcpy(normals, mesh.normals.data(), mesh.normals.size() * sizeof(Vec3f));
  auto* indices = static_cast<std::uint32_t*>(
      rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                              3 * sizeof(std::uint32_t), mesh.triangle_count()));
  std::memcpy(indices, mesh.indices.data(), mesh.indices.size() * sizeof(std::uint32_t));
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
  r.flags = 0;
  r.time = 0.0f;
  return r;
}

}  // namespace

struct EmbreeScene::Impl {
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
  unsigned ground_id = RTC_INVALID_GEOMETRY_ID;
};

EmbreeScene::EmbreeScene(const Scene& scene) : impl_(std::make_unique<Impl>()) {
  impl_->device = rtcNewDevice(nullptr);
  if (impl_->device == nullptr) throw std::runtime_error("Embree: could not create a device");
  rtcSetDeviceErrorFunction(impl_->device, report_embree_error, nullptr);
  impl_->scene = rtcNewScene(impl_->device);
  if (scene.ground.mesh.triangle_count() > 0) {
    RTCGeometry ground = make_ground(impl_->device, scene.ground.mesh);
    impl_->ground_id = rtcAttachGeometry(impl_->scene, ground);
    rtcReleaseGeometry(ground);
  }
  rtcCommitScene(impl_->scene);
}

EmbreeScene::~EmbreeScene() {
  if (impl_->scene) rtcReleaseScene(impl_->scene);
  if (impl_->device) rtcReleaseDevice(impl_->device);
}

std::optional<Hit> EmbreeScene::intersect(const Ray& ray, float t_near, float t_far) const {
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
  hit.geometric_normal = normalize(Vec3f{rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z});
  hit.object = ObjectClass::ground;
  float n[3];
  RTCGeometry geom = rtcGetGeometry(impl_->scene, rh.hit.geomID);
  rtcInterpolate0(geom, rh.hit.primID, rh.hit.u, rh.hit.v, RTC_BUFFER_TYPE_VERTEX_ATTRIBUTE, 0, n,
                  3);
  const Vec3f shading{n[0], n[1], n[2]};
  const float len = length(shading);
  hit.shading_normal = len > 0.0f ? shading / len : hit.geometric_normal;
  return hit;
}

bool EmbreeScene::occluded(const Ray& ray, float t_near, float t_far) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRay r = to_rtc(ray, t_near, t_far);
  rtcOccluded1(impl_->scene, &context, &r);
  return r.tfar < 0.0f;  // Embree sets tfar to -inf on a hit
}

}  // namespace landsim::renderer
