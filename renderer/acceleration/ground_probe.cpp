#include "renderer/acceleration/ground_probe.h"

#include <embree3/rtcore.h>

#include <algorithm>
#include <cstring>
#include <limits>
#include <stdexcept>

namespace landsim::renderer {

struct GroundProbe::Impl {
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
  float top = 0.0f;  // rays start above the highest vertex
  ~Impl() {
    if (scene) rtcReleaseScene(scene);
    if (device) rtcReleaseDevice(device);
  }
};

GroundProbe::GroundProbe(const terrain::GroundMesh& mesh) : impl_(std::make_unique<Impl>()) {
  impl_->device = rtcNewDevice(nullptr);
  if (impl_->device == nullptr) throw std::runtime_error("Embree failed to create its device");
  impl_->scene = rtcNewScene(impl_->device);
  float top = 0.0f;
  for (const Vec3f& v : mesh.vertices) top = std::max(top, v.z);
  impl_->top = top + 100.0f;
  if (mesh.triangle_count() > 0) {
    RTCGeometry geom = rtcNewGeometry(impl_->device, RTC_GEOMETRY_TYPE_TRIANGLE);
    void* v = rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                      sizeof(Vec3f), mesh.vertices.size());
    void* i = rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                      3 * sizeof(std::uint32_t), mesh.triangle_count());
    if (v == nullptr || i == nullptr)
      throw std::runtime_error("Embree could not allocate the ground probe's buffers");
    std::memcpy(v, mesh.vertices.data(), mesh.vertices.size() * sizeof(Vec3f));
    std::memcpy(i, mesh.indices.data(), mesh.indices.size() * sizeof(std::uint32_t));
    rtcCommitGeometry(geom);
    rtcAttachGeometry(impl_->scene, geom);
    rtcReleaseGeometry(geom);
  }
  rtcCommitScene(impl_->scene);
}

GroundProbe::~GroundProbe() = default;

std::optional<double> GroundProbe::height(double x, double y) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit rh{};
  rh.ray.org_x = static_cast<float>(x);
  rh.ray.org_y = static_cast<float>(y);
  rh.ray.org_z = impl_->top;
  rh.ray.dir_z = -1.0f;
  rh.ray.tnear = 0.0f;
  rh.ray.tfar = std::numeric_limits<float>::infinity();
  rh.ray.mask = 0xffffffffu;
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(impl_->scene, &context, &rh);
  if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return std::nullopt;
  return static_cast<double>(impl_->top) - static_cast<double>(rh.ray.tfar);
}

bool GroundProbe::occluded(const Vec3& from, const Vec3& to) const {
  const Vec3 d = to - from;
  const double distance = length(d);
  if (distance <= 0.0) return false;
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRay ray{};
  ray.org_x = static_cast<float>(from.x);
  ray.org_y = static_cast<float>(from.y);
  ray.org_z = static_cast<float>(from.z);
  ray.dir_x = static_cast<float>(d.x / distance);
  ray.dir_y = static_cast<float>(d.y / distance);
  ray.dir_z = static_cast<float>(d.z / distance);
  ray.tnear = 0.0f;
  ray.tfar = static_cast<float>(distance * (1.0 - 1e-4));  // the end point's own ground aside
  ray.mask = 0xffffffffu;
  rtcOccluded1(impl_->scene, &context, &ray);
  return ray.tfar < 0.0f;  // Embree marks a blocked ray with tfar = -inf
}

}  // namespace landsim::renderer
