#include "scenes/obj_export.h"

#include <fmt/format.h>
#include <fmt/os.h>

#include <array>
#include <stdexcept>

#include "core/atomic_file.h"

namespace landsim::scenes {

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

}  // namespace landsim::scenes
