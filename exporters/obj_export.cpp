#include "exporters/obj_export.h"

#include <fmt/compile.h>
#include <fmt/format.h>

#include <fstream>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <stdexcept>

#include <tbb/parallel_for.h>

#include "core/atomic_file.h"
#include "core/input_error.h"

namespace landsim::exporters {
namespace {

// OBJ lines formatted with compiled format strings (no parsing per line) into a buffer that
// goes to the file a megabyte at a time: formatting is most of writing a tree's OBJ.
class ObjFile {
 public:
  explicit ObjFile(const std::filesystem::path& path) : out_(path, std::ios::binary) {
    if (!out_) throw std::runtime_error("cannot write " + path.string());
  }
  template <typename Format, typename... Args>
  void print(const Format& format, const Args&... args) {
    fmt::format_to(std::back_inserter(buffer_), format, args...);
    if (buffer_.size() > (1u << 20)) flush();
  }
  // Lines 0 to count - 1, `line(buffer, i)` formatting line i: chunks formatted in parallel,
  // written in order (the file is the same on any thread count), a batch at a time so that
  // little of the file is held in memory.
  template <typename Line>
  void print_lines(std::size_t count, const Line& line) {
    constexpr std::size_t kChunk = 8192, kBatch = 8;
    flush();
    std::vector<fmt::memory_buffer> chunks(kBatch);
    for (std::size_t first = 0; first < count; first += kChunk * kBatch) {
      const std::size_t n = std::min(kBatch, (count - first + kChunk - 1) / kChunk);
      tbb::parallel_for(std::size_t{0}, n, [&](std::size_t k) {
        chunks[k].clear();
        const std::size_t begin = first + k * kChunk, end = std::min(count, begin + kChunk);
        for (std::size_t i = begin; i < end; ++i) line(chunks[k], i);
      });
      for (std::size_t k = 0; k < n; ++k)
        out_.write(chunks[k].data(), static_cast<std::streamsize>(chunks[k].size()));
    }
  }
  // Written and closed; throws when the file could not be written.
  void close(const std::filesystem::path& path) {
    flush();
    out_.close();
    if (!out_) throw std::runtime_error("cannot write " + path.string());
  }

 private:
  void flush() {
    out_.write(buffer_.data(), static_cast<std::streamsize>(buffer_.size()));
    buffer_.clear();
  }
  std::ofstream out_;
  fmt::memory_buffer buffer_;
};

}  // namespace

void write_obj(const trees::TreeGeometry& geometry, const std::filesystem::path& path) {
  static constexpr std::array<const char*, trees::kGroupCount> kNames{"trunk", "level1", "level2",
                                                                      "level3plus", "leaves"};
  AtomicFile out(path);
  {
    ObjFile file(out.temp_path());
    file.print(FMT_COMPILE("# landsim tree: stems and leaves, metres, z up\n"));
    std::size_t base = 1;  // OBJ indices start at 1 and run across groups
    for (std::size_t g = 0; g < geometry.groups.size(); ++g) {
      const trees::TriangleSet& t = geometry.groups[g].triangles;
      if (t.indices.empty()) continue;
      file.print(FMT_COMPILE("g {}\n"), kNames[g]);
      file.print_lines(t.vertices.size(), [&](fmt::memory_buffer& b, std::size_t i) {
        const Vec3f& v = t.vertices[i];
        fmt::format_to(std::back_inserter(b), FMT_COMPILE("v {} {} {}\n"), v.x, v.y, v.z);
      });
      file.print_lines(t.normals.size(), [&](fmt::memory_buffer& b, std::size_t i) {
        const Vec3f& n = t.normals[i];
        fmt::format_to(std::back_inserter(b), FMT_COMPILE("vn {} {} {}\n"), n.x, n.y, n.z);
      });
      file.print_lines(t.indices.size() / 3, [&](fmt::memory_buffer& b, std::size_t f) {
        const std::size_t i = 3 * f, a = base + t.indices[i], c1 = base + t.indices[i + 1],
                          c2 = base + t.indices[i + 2];
        fmt::format_to(std::back_inserter(b), FMT_COMPILE("f {}//{} {}//{} {}//{}\n"), a, a, c1, c1,
                       c2, c2);
      });
      base += t.vertices.size();
    }
    file.close(out.temp_path());
  }  // closed (and flushed) before the rename
  out.commit();
}

namespace {

// The instances to export: the `max` nearest `near`, nearest first.
std::vector<std::size_t> nearest_instances(const renderer::Scene& scene, std::size_t max,
                                           const Vec3& near) {
  std::vector<std::size_t> order(scene.instances.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  const std::size_t n = std::min(max, order.size());
  std::partial_sort(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(n), order.end(),
                    [&](std::size_t a, std::size_t b) {
                      return length(scene.instances[a].position - near) <
                             length(scene.instances[b].position - near);
                    });
  order.resize(n);
  // Listed in the scene's order, so each row's instance id is the EXR's (docs/OUTPUTS.md).
  std::sort(order.begin(), order.end());
  return order;
}

std::size_t triangle_count(const trees::TreeGeometry& g) {
  std::size_t n = 0;
  for (const trees::GroupGeometry& group : g.groups) n += group.triangles.indices.size() / 3;
  return n;
}

// An object's name as an OBJ group name: no white space (letters, digits, '_', '-', '.' kept).
std::string obj_name(const std::string& name) {
  std::string out;
  for (const char ch : name) {
    const auto c = static_cast<unsigned char>(ch);
    out += std::isalnum(c) || ch == '_' || ch == '-' || ch == '.' ? ch : '_';
  }
  return out;
}

// A flattened OBJ grows with every tree's triangles; past this it is refused before writing.
constexpr double kMaxFlattenedBytes = 4e9;

// About 30 bytes per vertex line and 25 per face line; a mesh has about as many vertices as
// triangles.
double flattened_bytes(const renderer::Scene& scene, const std::vector<std::size_t>& chosen) {
  double bytes = static_cast<double>(scene.ground.mesh.triangle_count()) * 55.0;
  for (std::size_t i : chosen)
    bytes += static_cast<double>(
                 triangle_count(scene.prototypes[scene.instances[i].prototype].geometry)) *
             55.0;
  return bytes;
}

}  // namespace

SceneObjSummary write_scene_obj(const renderer::Scene& scene, const std::filesystem::path& path,
                                const SceneObjOptions& options) {
  SceneObjSummary summary;
  const std::vector<std::size_t> chosen = nearest_instances(scene, options.max_trees, options.near);
  if (options.flatten && flattened_bytes(scene, chosen) > kMaxFlattenedBytes)
    throw InputError(fmt::format(
        "export-obj --flatten: {} trees would write about {:.1f} GB; lower --max-trees, or leave "
        "out --flatten (each prototype once, the instances listed)",
        chosen.size(), flattened_bytes(scene, chosen) / 1e9));
  // Terrain coordinates need doubles (UTM eastings have six digits before the point).
  const Vec3 shift = options.terrain_frame ? scene.origin : Vec3{};
  std::vector<bool> used(scene.prototypes.size(), false);
  for (std::size_t i : chosen) used[scene.instances[i].prototype] = true;
  AtomicFile out(path);
  {
    ObjFile file(out.temp_path());
    file.print(FMT_COMPILE("# landsim scene: ground, {} objects and {} trees ({}), {} frame, "
                           "metres, z up\n"),
               scene.objects.size(), chosen.size(),
               options.flatten ? "flattened" : "prototypes once, instances listed",
               options.terrain_frame ? "terrain" : "scene");
    std::size_t base = 1;
    const auto mesh = [&](const std::string& name, const std::vector<Vec3f>& vertices,
                          const std::vector<std::uint32_t>& indices, const auto& transform) {
      if (indices.empty()) return;
      file.print(FMT_COMPILE("g {}\n"), name);
      for (const Vec3f& v : vertices) {
        const Vec3 w = transform(v);
        file.print(FMT_COMPILE("v {:.4f} {:.4f} {:.4f}\n"), w.x, w.y, w.z);
      }
      for (std::size_t i = 0; i + 2 < indices.size(); i += 3)
        file.print(FMT_COMPILE("f {} {} {}\n"), base + indices[i], base + indices[i + 1],
                   base + indices[i + 2]);
      base += vertices.size();
    };
    mesh("ground", scene.ground.mesh.vertices, scene.ground.mesh.indices,
         [&](const Vec3f& v) { return Vec3(v) + shift; });
    summary.ground_triangles = scene.ground.mesh.triangle_count();
    // Scene objects ([[objects]]) in place, one group each: there are few of them.
    for (const renderer::ObjectInstance& o : scene.objects) {
      const renderer::ObjectPrototype& p = scene.object_prototypes[o.prototype];
      mesh("object_" + obj_name(o.name), p.vertices, p.indices,
           [&](const Vec3f& v) { return o.apply(v) + shift; });
      summary.object_triangles += p.triangle_count();
    }
    if (options.flatten) {
      for (std::size_t i : chosen) {
        const renderer::TreeInstance& inst = scene.instances[i];
        const double c = std::cos(inst.rotation) * inst.scale,
                     s = std::sin(inst.rotation) * inst.scale;
        const auto place = [&](const Vec3f& v) {
          return inst.apply_lean(Vec3{c * v.x - s * v.y, s * v.x + c * v.y, inst.scale * v.z}) +
                 inst.position + shift;
        };
        for (const trees::GroupGeometry& g : scene.prototypes[inst.prototype].geometry.groups)
          mesh("tree", g.triangles.vertices, g.triangles.indices, place);
        summary.tree_triangles += triangle_count(scene.prototypes[inst.prototype].geometry);
      }
    } else {
      // Each prototype once, in its own frame (trunk base at the origin); the instance list
      // places it.
      for (std::size_t p = 0; p < scene.prototypes.size(); ++p) {
        if (!used[p]) continue;
        for (const trees::GroupGeometry& g : scene.prototypes[p].geometry.groups)
          mesh("prototype_" + std::to_string(p), g.triangles.vertices, g.triangles.indices,
               [](const Vec3f& v) { return Vec3(v); });
        summary.tree_triangles += triangle_count(scene.prototypes[p].geometry);
        ++summary.prototypes;
      }
    }
    file.close(out.temp_path());
  }
  if (!options.flatten) {
    summary.instances_file = path;
    summary.instances_file.replace_extension(".instances.csv");
    AtomicFile list(summary.instances_file);
    {
      std::ofstream csv(list.temp_path(), std::ios::binary);
      csv << "# Tree instances of " << path.filename().string()
          << ": OBJ group prototype_<prototype>, rotated about z by rotation_deg, scaled, "
             "leaned in the wind (a turn about the horizontal axis (lean_x, lean_y) by its "
             "length in degrees), its trunk base moved to x, y, z ("
          << (options.terrain_frame ? "terrain" : "scene") << " frame, metres)\n"
          << "instance,prototype,x,y,z,rotation_deg,scale,lean_x_deg,lean_y_deg\n";
      for (std::size_t i : chosen) {
        const renderer::TreeInstance& inst = scene.instances[i];
        const Vec3 at = inst.position + shift;
        constexpr double kDegrees = 180.0 / 3.14159265358979323846;
        csv << fmt::format("{},{},{:.4f},{:.4f},{:.4f},{:.4f},{:.6f},{:.4f},{:.4f}\n", i,
                           inst.prototype, at.x, at.y, at.z, inst.rotation * kDegrees, inst.scale,
                           inst.lean.x * kDegrees, inst.lean.y * kDegrees);
      }
      if (!csv) throw std::runtime_error("cannot write " + summary.instances_file.string());
    }
    list.commit();
  }
  out.commit();
  summary.instances = chosen.size();
  summary.bytes = std::filesystem::file_size(path);
  return summary;
}

}  // namespace landsim::exporters
