#include "exporters/obj_export.h"

#include <fmt/format.h>
#include <fmt/os.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include "core/atomic_file.h"

namespace landsim::exporters {

void write_obj(const trees::TreeGeometry& geometry, const std::filesystem::path& path) {
  static constexpr std::array<const char*, trees::kGroupCount> kNames{"trunk", "level1", "level2",
                                                                      "level3plus", "leaves"};
  AtomicFile out(path);
  {
    auto file = fmt::output_file(out.temp_path().string());
    file.print("# landsim tree: stems and leaves, metres, z up\n");
    std::size_t base = 1;  // OBJ indices start at 1 and run across groups
    for (std::size_t g = 0; g < geometry.groups.size(); ++g) {
      const trees::TriangleSet& t = geometry.groups[g].triangles;
      if (t.indices.empty()) continue;
      file.print("g {}\n", kNames[g]);
      for (const Vec3f& v : t.vertices) file.print("v {} {} {}\n", v.x, v.y, v.z);
      for (const Vec3f& n : t.normals) file.print("vn {} {} {}\n", n.x, n.y, n.z);
      for (std::size_t i = 0; i + 2 < t.indices.size(); i += 3) {
        const std::size_t a = base + t.indices[i], b = base + t.indices[i + 1],
                          c = base + t.indices[i + 2];
        file.print("f {}//{} {}//{} {}//{}\n", a, a, b, b, c, c);
      }
      base += t.vertices.size();
    }
  }  // closed (and flushed) before the rename
  out.commit();
}

void write_scene_obj(const renderer::Scene& scene, const std::filesystem::path& path,
                     std::size_t max_trees, const Vec3& near) {
  AtomicFile out(path);
  {
    auto file = fmt::output_file(out.temp_path().string());
    file.print("# landsim scene: ground and {} nearest trees, scene frame, metres, z up\n",
               max_trees);
    std::size_t base = 1;
    const auto mesh = [&](const char* name, const std::vector<Vec3f>& vertices,
                          const std::vector<std::uint32_t>& indices, const auto& transform) {
      if (indices.empty()) return;
      file.print("g {}\n", name);
      for (const Vec3f& v : vertices) {
        const Vec3f w = transform(v);
        file.print("v {} {} {}\n", w.x, w.y, w.z);
      }
      for (std::size_t i = 0; i + 2 < indices.size(); i += 3) {
        file.print("f {} {} {}\n", base + indices[i], base + indices[i + 1], base + indices[i + 2]);
      }
      base += vertices.size();
    };
    mesh("ground", scene.ground.mesh.vertices, scene.ground.mesh.indices,
         [](const Vec3f& v) { return v; });
    std::vector<std::size_t> order(scene.instances.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      return length(scene.instances[a].position - near) <
             length(scene.instances[b].position - near);
    });
    for (std::size_t k = 0; k < std::min(max_trees, order.size()); ++k) {
      const renderer::TreeInstance& inst = scene.instances[order[k]];
      const auto c = static_cast<float>(std::cos(inst.rotation) * inst.scale),
                 s = static_cast<float>(std::sin(inst.rotation) * inst.scale);
      const auto place = [&](const Vec3f& v) {
        return Vec3f{c * v.x - s * v.y, s * v.x + c * v.y, static_cast<float>(inst.scale) * v.z} +
               Vec3f(inst.position);
      };
      for (const trees::GroupGeometry& g : scene.prototypes[inst.prototype].geometry.groups) {
        mesh("tree", g.triangles.vertices, g.triangles.indices, place);
      }
    }
  }
  out.commit();
}

}  // namespace landsim::exporters
