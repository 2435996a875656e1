// Embree's memory per primitive and per instance, measured as the growth of this process's
// resident memory while building scenes of a million of each (issue 27). The constants of
// renderer/acceleration/memory_model.h come from here; rerun after an Embree upgrade:
//   build/bin/memory_bench
// Not a Google Benchmark: resident memory is per process, and each figure is one build.
#include <embree3/rtcore.h>

#include <fmt/format.h>
#include "core/process_memory.h"
#include "renderer/output/image_io.h"

#include <atomic>
#include <cstdint>
#include <cstring>
#include <functional>
#include <vector>

#include "core/process_memory.h"
#include "trees/species.h"

namespace {

constexpr std::size_t kCount = 1'000'000;

void* buffer(RTCGeometry g, RTCBufferType type, RTCFormat format, std::size_t stride,
             std::size_t n) {
  return rtcSetNewGeometryBuffer(g, type, 0, format, stride, n);
}

// A strip of `n` triangles over n / 2 + 1 vertex pairs, indexed like a tree's tubes (about
// one vertex per triangle), with a normal per vertex as the renderer attaches.
RTCScene triangles(RTCDevice device, std::size_t n) {
  RTCScene s = rtcNewScene(device);
  RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
  const std::size_t verts = n + 2;
  auto* v = static_cast<float*>(buffer(g, RTC_BUFFER_TYPE_VERTEX, RTC_FORMAT_FLOAT3, 12, verts));
  for (std::size_t i = 0; i < verts; ++i) {
    v[3 * i] = static_cast<float>(i / 2) * 0.01f;
    v[3 * i + 1] = static_cast<float>(i % 2);
    v[3 * i + 2] = static_cast<float>((i * 7919) % 1000) * 0.001f;
  }
  rtcSetGeometryVertexAttributeCount(g, 1);
  auto* nrm = static_cast<float*>(
      buffer(g, RTC_BUFFER_TYPE_VERTEX_ATTRIBUTE, RTC_FORMAT_FLOAT3, 12, verts));
  for (std::size_t i = 0; i < 3 * verts; ++i) nrm[i] = 0.577f;
  auto* idx =
      static_cast<std::uint32_t*>(buffer(g, RTC_BUFFER_TYPE_INDEX, RTC_FORMAT_UINT3, 12, n));
  for (std::size_t t = 0; t < n; ++t) {
    idx[3 * t] = static_cast<std::uint32_t>(t);
    idx[3 * t + 1] = static_cast<std::uint32_t>(t + 1);
    idx[3 * t + 2] = static_cast<std::uint32_t>(t + 2);
  }
  rtcCommitGeometry(g);
  rtcAttachGeometry(s, g);
  rtcReleaseGeometry(g);
  rtcCommitScene(s);
  return s;
}

// `n` primitives of a FLOAT4 type (curve segments or discs), one point each plus one.
RTCScene float4_prims(RTCDevice device, RTCGeometryType type, std::size_t n, bool indexed) {
  RTCScene s = rtcNewScene(device);
  RTCGeometry g = rtcNewGeometry(device, type);
  const std::size_t points = n + 1;
  auto* v = static_cast<float*>(buffer(g, RTC_BUFFER_TYPE_VERTEX, RTC_FORMAT_FLOAT4, 16, points));
  for (std::size_t i = 0; i < points; ++i) {
    v[4 * i] = static_cast<float>(i % 1000) * 0.1f;
    v[4 * i + 1] = static_cast<float>(i / 1000) * 0.1f;
    v[4 * i + 2] = static_cast<float>((i * 7919) % 1000) * 0.001f;
    v[4 * i + 3] = 0.02f;
  }
  if (type == RTC_GEOMETRY_TYPE_ORIENTED_DISC_POINT) {
    auto* nrm =
        static_cast<float*>(buffer(g, RTC_BUFFER_TYPE_NORMAL, RTC_FORMAT_FLOAT3, 12, points));
    for (std::size_t i = 0; i < 3 * points; ++i) nrm[i] = 0.577f;
  }
  if (indexed) {
    auto* idx =
        static_cast<std::uint32_t*>(buffer(g, RTC_BUFFER_TYPE_INDEX, RTC_FORMAT_UINT, 4, n));
    for (std::size_t i = 0; i < n; ++i) idx[i] = static_cast<std::uint32_t>(i);
  }
  rtcCommitGeometry(g);
  rtcAttachGeometry(s, g);
  rtcReleaseGeometry(g);
  rtcCommitScene(s);
  return s;
}

// `n` instances of a one-triangle scene on a grid, as the renderer attaches trees.
RTCScene instances(RTCDevice device, std::size_t n) {
  RTCScene proto = triangles(device, 1);
  RTCScene s = rtcNewScene(device);
  for (std::size_t i = 0; i < n; ++i) {
    RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_INSTANCE);
    rtcSetGeometryInstancedScene(g, proto);
    const float m[12] = {1,
                         0,
                         0,
                         0,
                         1,
                         0,
                         0,
                         0,
                         1,
                         static_cast<float>(i % 1000) * 5.0f,
                         static_cast<float>(i / 1000) * 5.0f,
                         0};
    rtcSetGeometryTransform(g, 0, RTC_FORMAT_FLOAT3X4_COLUMN_MAJOR, m);
    rtcSetGeometryMask(g, 0xffffffffu);
    rtcCommitGeometry(g);
    rtcAttachGeometry(s, g);
    rtcReleaseGeometry(g);
  }
  rtcCommitScene(s);
  rtcReleaseScene(proto);
  return s;
}

// Resident bytes per element that `build` adds, measured with the scene still alive.
double bytes_per(const char* what, const std::function<RTCScene(RTCDevice)>& build) {
  RTCDevice device = rtcNewDevice(nullptr);
  const std::size_t before = landsim::resident_bytes();
  RTCScene s = build(device);
  const std::size_t after = landsim::resident_bytes();
  rtcReleaseScene(s);
  rtcReleaseDevice(device);
  const double per = static_cast<double>(after - before) / static_cast<double>(kCount);
  fmt::print("{:<28}{:8.1f} bytes\n", what, per);
  return per;
}

// Embree's own count of the bytes it holds (its memory monitor): a tree's freed generation
// arrays would hide the growth of resident memory.
std::atomic<long long> g_embree_bytes{0};

bool monitor(void*, ssize_t bytes, bool) {
  g_embree_bytes += bytes;
  return true;
}

// A whole tree at full detail as the renderer attaches it (each group one mesh with a normal
// per vertex): its meshes are less regular than a strip, and Embree's spatial splits
// duplicate more references.
void tree_at_full_detail(const char* species_file) {
  const landsim::trees::Species species = landsim::trees::load_species(
      std::string(LANDSIM_SOURCE_DIR) + "/data/species/" + species_file);
  landsim::trees::TreeOptions options;
  options.seed = 1;
  const landsim::trees::TreeGeometry tree = landsim::trees::generate(species, options).geometry;
  RTCDevice device = rtcNewDevice(nullptr);
  rtcSetDeviceMemoryMonitorFunction(device, monitor, nullptr);
  g_embree_bytes = 0;
  RTCScene s = rtcNewScene(device);
  for (const landsim::trees::GroupGeometry& group : tree.groups) {
    const landsim::trees::TriangleSet& t = group.triangles;
    if (t.indices.empty()) continue;
    RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    std::memcpy(buffer(g, RTC_BUFFER_TYPE_VERTEX, RTC_FORMAT_FLOAT3, 12, t.vertices.size()),
                t.vertices.data(), 12 * t.vertices.size());
    rtcSetGeometryVertexAttributeCount(g, 1);
    std::memcpy(
        buffer(g, RTC_BUFFER_TYPE_VERTEX_ATTRIBUTE, RTC_FORMAT_FLOAT3, 12, t.normals.size()),
        t.normals.data(), 12 * t.normals.size());
    std::memcpy(buffer(g, RTC_BUFFER_TYPE_INDEX, RTC_FORMAT_UINT3, 12, t.triangle_count()),
                t.indices.data(), 4 * t.indices.size());
    rtcCommitGeometry(g);
    rtcAttachGeometry(s, g);
    rtcReleaseGeometry(g);
  }
  rtcCommitScene(s);
  const double triangles = static_cast<double>(tree.triangle_count());
  fmt::print("{:<28}{:8.1f} bytes per triangle ({:.0f} triangles)\n", species_file,
             static_cast<double>(g_embree_bytes) / triangles, triangles);
  rtcReleaseScene(s);
  rtcReleaseDevice(device);
}

}  // namespace

int main() {
  // First, while little else is resident: what loading the image module adds (its
  // libraries' pages), the estimate's kImageModuleBytes.
  const std::size_t before = landsim::resident_bytes();
  landsim::renderer::image_io();
  fmt::print("image module (OpenImageIO, OpenColorIO): {:.0f} MB resident\n",
             static_cast<double>(landsim::resident_bytes() - before) / 1e6);
  fmt::print("Embree resident memory per element ({} of each):\n", kCount);
  bytes_per("triangle (indexed, normals)", [](RTCDevice d) { return triangles(d, kCount); });
  bytes_per("round linear curve segment", [](RTCDevice d) {
    return float4_prims(d, RTC_GEOMETRY_TYPE_ROUND_LINEAR_CURVE, kCount, true);
  });
  bytes_per("oriented disc point", [](RTCDevice d) {
    return float4_prims(d, RTC_GEOMETRY_TYPE_ORIENTED_DISC_POINT, kCount, false);
  });
  bytes_per("instance", [](RTCDevice d) { return instances(d, kCount); });
  fmt::print("Trees at full detail in the renderer's Embree scene:\n");
  for (const char* file : {"quaking_aspen.toml", "ca_black_oak.toml", "black_tupelo.toml"})
    tree_at_full_detail(file);
  return 0;
}
