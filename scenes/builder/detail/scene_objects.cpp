#include "scenes/builder/detail/scene_objects.h"

#include <fmt/format.h>
#include <spdlog/spdlog.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <optional>
#include <vector>

#include "core/counter_rng.h"
#include "core/input_error.h"
#include "core/input_warnings.h"
#include "renderer/acceleration/ground_probe.h"
#include "renderer/materials/object_texture.h"
#include "scenes/builder/detail/mesh_file_check.h"
#include "scenes/builder/detail/object_siting.h"
#include "scenes/builder/mesh_io.h"

namespace landsim::scenes::detail {
namespace {

using Matrix3 = std::array<double, 9>;  // row-major

// Samples per side of the footprint where align_to_ground fits the ground's plane.
constexpr int kPlaneSamples = 9;

Vec3 mul(const Matrix3& m, const Vec3& v) {
  return {m[0] * v.x + m[1] * v.y + m[2] * v.z, m[3] * v.x + m[4] * v.y + m[5] * v.z,
          m[6] * v.x + m[7] * v.y + m[8] * v.z};
}

Matrix3 mul(const Matrix3& a, const Matrix3& b) {
  Matrix3 c{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) c[3 * i + j] += a[3 * i + k] * b[3 * k + j];
  return c;
}

// Heading, clockwise from north: the object's front (+y) turns toward east for 90 degrees.
Matrix3 heading_rotation(double heading_deg) {
  const double a = -heading_deg * std::numbers::pi / 180.0;
  const double c = std::cos(a), s = std::sin(a);
  return {c, -s, 0.0, s, c, 0.0, 0.0, 0.0, 1.0};
}

// The shortest rotation taking +z to the unit vector `n`: about z x n.
Matrix3 tilt_to(const Vec3& n) {
  const Vec3 k{-n.y, n.x, 0.0};  // z x n
  const double sin_angle = length(k);
  if (sin_angle < 1e-12) return {1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0};
  const double angle = std::atan2(sin_angle, n.z);
  const Vec3 u = k / sin_angle;
  const Vec3 x = rotate_about({1, 0, 0}, u, angle), y = rotate_about({0, 1, 0}, u, angle),
             z = rotate_about({0, 0, 1}, u, angle);
  return {x.x, y.x, z.x, x.y, y.y, z.y, x.z, y.z, z.z};  // row-major, the columns turned
}

std::string where(const ObjectSettings& o, const std::string& location, std::string_view key) {
  return fmt::format("{}: [{}] {}", location, o.path, key);
}

// A file's mesh in the object frame (metres per file unit aside): z up, front toward +y.
// Files are y up with their front toward +z (glTF's convention, and Blender's OBJ export),
// so (x, y, z) -> (-x, z, y), a rotation; or already z up with `z_up`.
renderer::ObjectPrototype to_prototype(const MeshData& mesh, const ObjectSettings& o) {
  renderer::ObjectPrototype p;
  p.file = o.file;
  const std::size_t n = mesh.positions.size() / 3;
  const auto axes = [&](const float* v) {
    return o.z_up ? Vec3f{v[0], v[1], v[2]} : Vec3f{-v[0], v[2], v[1]};
  };
  p.vertices.reserve(n);
  p.normals.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    const float* v = &mesh.positions[3 * i];
    if (!std::isfinite(v[0]) || !std::isfinite(v[1]) || !std::isfinite(v[2]))
      throw InputError(fmt::format("{}: {}: vertex {} is not a finite number ({}, {}, {})",
                                   where(o, o.file_location, "file"), o.file, i, v[0], v[1], v[2]));
    p.vertices.push_back(axes(v));
    const Vec3f nv = axes(&mesh.normals[3 * i]);
    p.normals.push_back(std::isfinite(nv.x + nv.y + nv.z) ? nv : Vec3f{});
  }
  p.uvs = mesh.uvs;
  p.indices = mesh.indices;
  p.triangle_material = mesh.triangle_material;
  for (const MeshMaterial& m : mesh.materials) p.material_names.push_back(m.name);
  return p;
}

// The file's materials with the object's overrides applied; textures read once per path.
std::vector<renderer::ObjectMaterial> object_materials(
    const ObjectSettings& o, const MeshData& mesh,
    std::map<std::string, std::shared_ptr<const renderer::ObjectTexture>>& textures) {
  std::vector<renderer::ObjectMaterial> out;
  for (const MeshMaterial& m : mesh.materials) {
    renderer::ObjectMaterial r;
    r.base_colour = {m.base_colour[0], m.base_colour[1], m.base_colour[2]};
    r.roughness = m.roughness;
    r.metallic = m.metallic;
    if (!m.texture.empty()) {
      auto& t = textures[m.texture];
      if (!t) {
        try {
          t = renderer::load_object_texture(m.texture);
        } catch (const InputError& e) {
          throw InputError(where(o, o.file_location, "file") + ": " + o.file + ": " + e.what());
        }
      }
      r.texture = t;
    }
    if (m.embedded_texture)
      warn_input(
          fmt::format("{}: {}: material '{}' embeds its base-colour texture, which is not "
                      "read (its base colour factor is used)",
                      where(o, o.file_location, "file"), o.file, m.name));
    out.push_back(r);
  }
  for (const ObjectMaterialOverride& ov : o.materials) {
    std::vector<std::string> names;
    std::size_t k = 0;
    for (; k < mesh.materials.size() && mesh.materials[k].name != ov.material; ++k)
      names.push_back("'" + mesh.materials[k].name + "'");
    if (k == mesh.materials.size())
      throw InputError(fmt::format("{}: [{}.material] name: {} has no material '{}' (it has {})",
                                   ov.location, o.path, o.file, ov.material,
                                   fmt::join(names, ", ")));
    if (ov.albedo) out[k].base_colour = *ov.albedo;
    if (ov.roughness) out[k].roughness = *ov.roughness;
    if (ov.metallic) out[k].metallic = *ov.metallic;
  }
  return out;
}

// The normal of the plane fitted (least squares) to the ground under the object's
// footprint: a grid over its bounding rectangle in its own frame, turned by its heading.
Vec3 ground_plane_normal(const renderer::ObjectPrototype& p, const Matrix3& turn, const Vec3& at,
                         const renderer::GroundProbe& probe) {
  float x0 = std::numeric_limits<float>::max(), y0 = x0, x1 = -x0, y1 = -x0;
  for (const Vec3f& v : p.vertices) {
    x0 = std::min(x0, v.x);
    x1 = std::max(x1, v.x);
    y0 = std::min(y0, v.y);
    y1 = std::max(y1, v.y);
  }
  double s[6] = {0, 0, 0, 0, 0, 0}, t[3] = {0, 0, 0};  // normal equations of h = a + b x + c y
  for (int i = 0; i < kPlaneSamples; ++i)
    for (int j = 0; j < kPlaneSamples; ++j) {
      const Vec3 local{x0 + double(x1 - x0) * i / (kPlaneSamples - 1.0),
                       y0 + double(y1 - y0) * j / (kPlaneSamples - 1.0), 0.0};
      const Vec3 d = mul(turn, local);
      const std::optional<double> h = probe.height(at.x + d.x, at.y + d.y);
      if (!h) continue;  // reported by the placement below
      s[0] += 1;
      s[1] += d.x;
      s[2] += d.y;
      s[3] += d.x * d.x;
      s[4] += d.x * d.y;
      s[5] += d.y * d.y;
      t[0] += *h;
      t[1] += d.x * *h;
      t[2] += d.y * *h;
    }
  // Solve [[n, Sx, Sy], [Sx, Sxx, Sxy], [Sy, Sxy, Syy]] (a, b, c) = t by Cramer's rule.
  const Matrix3 m{s[0], s[1], s[2], s[1], s[3], s[4], s[2], s[4], s[5]};
  const auto det = [](const Matrix3& a) {
    return a[0] * (a[4] * a[8] - a[5] * a[7]) - a[1] * (a[3] * a[8] - a[5] * a[6]) +
           a[2] * (a[3] * a[7] - a[4] * a[6]);
  };
  const double d = det(m);
  if (std::abs(d) < 1e-12) return {0.0, 0.0, 1.0};  // a point-like footprint: upright
  Matrix3 mb = m, mc = m;
  for (int r = 0; r < 3; ++r) {
    mb[3 * r + 1] = t[r];
    mc[3 * r + 2] = t[r];
  }
  const double b = det(mb) / d, c = det(mc) / d;
  return normalize(Vec3{-b, -c, 1.0});
}

// Points of a triangle's surface at most this far apart (metres) are checked against the
// ground besides its corners: over a knoll a flat panel's corners lie on the flanks while
// the ground bulges through its middle (3 of 18 of its pixels were visible).
constexpr double kClearanceSpacing = 0.5;
constexpr int kMostClearanceSteps = 64;  // per triangle edge

// How far to raise the object (its turned vertices about `at`) so that no point of its
// surface is below the ground and one touches it: its corners and a grid of points over each
// larger triangle. Empty when a point is outside the terrain or over a nodata hole.
std::optional<double> lift_onto_ground(const renderer::ObjectPrototype& p,
                                       const std::vector<Vec3>& turned, const Vec3& at,
                                       const renderer::GroundProbe& probe) {
  constexpr double kNoGround = std::numeric_limits<double>::quiet_NaN();
  // How far the ground stands above the point q; NaN where there is none.
  const auto rise = [&](const Vec3& q) {
    const std::optional<double> h = probe.height(at.x + q.x, at.y + q.y);
    return h ? *h - q.z : kNoGround;
  };
  // Every vertex once, then the points inside the larger triangles (not their corners).
  const std::size_t vertices = turned.size(), n = p.triangle_count();
  std::vector<double> lift(vertices + n, -std::numeric_limits<double>::infinity());
  tbb::parallel_for(std::size_t{0}, vertices, [&](std::size_t v) { lift[v] = rise(turned[v]); });
  tbb::parallel_for(std::size_t{0}, n, [&](std::size_t t) {
    const Vec3& a = turned[p.indices[3 * t]];
    const Vec3& b = turned[p.indices[3 * t + 1]];
    const Vec3& c = turned[p.indices[3 * t + 2]];
    const double longest = std::max({length(b - a), length(c - b), length(a - c)});
    const int steps =
        std::min(static_cast<int>(std::ceil(longest / kClearanceSpacing)), kMostClearanceSteps);
    double& most = lift[vertices + t];
    for (int i = 0; i <= steps; ++i)
      for (int j = 0; i + j <= steps; ++j) {
        if ((i == 0 && j == 0) || i == steps || j == steps) continue;  // a corner
        const double r = rise(a + (b - a) * (double(i) / steps) + (c - a) * (double(j) / steps));
        if (std::isnan(r)) {
          most = kNoGround;
          return;
        }
        most = std::max(most, r);
      }
  });
  double most = -std::numeric_limits<double>::infinity();
  for (const double l : lift) {
    if (std::isnan(l)) return std::nullopt;
    most = std::max(most, l);
  }
  return most;
}

// An object's transform (object frame -> scene frame, column-major 3 x 4) and the radius of
// its footprint about its position.
struct ObjectPlacement {
  std::array<double, 12> transform{};
  double footprint_radius = 0.0;
};

// Places `p` for `o`: heading, then (aligned) the tilt to the ground's plane, scaled; then
// lowered onto the ground until its surface touches it and no point of it is below it.
ObjectPlacement place(const renderer::ObjectPrototype& p, const ObjectSettings& o,
                      const Vec3& origin, const renderer::GroundProbe& probe) {
  const Vec3 at{o.x - origin.x, o.y - origin.y, 0.0};
  const auto off_ground = [&] {
    return InputError(fmt::format(
        "{}: the object at ({}, {}) stands partly outside the terrain or over a nodata hole",
        where(o, o.position_location, "position"), o.x, o.y));
  };
  if (!probe.height(at.x, at.y)) throw off_ground();
  const Matrix3 turn = heading_rotation(o.heading_deg);
  Matrix3 linear = turn;
  if (o.align_to_ground && !o.z)
    linear = mul(tilt_to(ground_plane_normal(p, turn, at, probe)), turn);
  const double k = o.scale * o.unit_scale;
  for (double& v : linear) v *= k;
  ObjectPlacement out;
  std::vector<Vec3> turned(p.vertices.size());
  for (std::size_t i = 0; i < p.vertices.size(); ++i) {
    turned[i] = mul(linear, Vec3(p.vertices[i]));
    out.footprint_radius = std::max(out.footprint_radius, std::hypot(turned[i].x, turned[i].y));
  }
  double z = o.z ? *o.z - origin.z : -std::numeric_limits<double>::infinity();
  if (!o.z) {
    const std::optional<double> lift = lift_onto_ground(p, turned, at, probe);
    if (!lift) throw off_ground();
    z = *lift;
  }
  // Column-major 3 x 4.
  out.transform = {linear[0], linear[3], linear[6], linear[1], linear[4], linear[7],
                   linear[2], linear[5], linear[8], at.x,      at.y,      z};
  return out;
}

// Removes the trees whose trunk base lies within `radius` (horizontally) of (x, y).
void clear_trees(renderer::Scene& scene, double x, double y, double radius) {
  std::erase_if(scene.instances, [&](const renderer::TreeInstance& t) {
    return std::hypot(t.position.x - x, t.position.y - y) < radius;
  });
}

// The object with what it draws from the seed: its place by a view ([objects.place]) and a
// random heading. The draws mix [render] seed, the randomised image and the object's index.
ObjectSettings with_draws(const ObjectSettings& o, std::size_t index, const Scenario& s,
                          const renderer::ObjectPrototype& proto, const renderer::Scene& scene,
                          const renderer::GroundProbe& probe,
                          const std::vector<TakenGround>& taken) {
  if (!o.siting && !o.random_heading) return o;
  std::uint64_t seed = hash_combine(hash_combine(s.render.seed, s.variation), index);
  ObjectSettings drawn = o;
  if (o.siting) {
    seed = hash_combine(seed, o.siting->seed);
    const Site site = site_object(o, proto, scene, probe, taken, seed);
    drawn.x = site.x + scene.origin.x;
    drawn.y = site.y + scene.origin.y;
    drawn.heading_deg = site.heading_deg;
    drawn.position_location = o.siting->location;
    spdlog::info("{} placed at ({:.1f}, {:.1f}), heading {:.1f}: {:.0f}% of it seen from '{}'",
                 o.name, drawn.x, drawn.y, drawn.heading_deg, 100.0 * site.visible, o.siting->view);
  } else {
    drawn.heading_deg = 360.0 * CounterRng(seed, 0, 0).uniform(0);
  }
  return drawn;
}

}  // namespace

const MeshData& read_object_mesh(const ObjectSettings& o, std::map<std::string, MeshData>& files) {
  const auto found = files.find(o.file);
  if (found != files.end()) return found->second;
  check_mesh_file(o.file, where(o, o.file_location, "file"));
  MeshData mesh;
  std::string error;
  if (!mesh_io().read(o.file, mesh, error))
    throw InputError(fmt::format("{}: cannot read mesh {}: {}", where(o, o.file_location, "file"),
                                 o.file, error));
  if (mesh.indices.empty() && mesh.zero_area_faces > 0)
    throw InputError(fmt::format(
        "{}: {}: the mesh has no faces of any area (its {} triangles are all of zero area: never "
        "visible)",
        where(o, o.file_location, "file"), o.file, mesh.zero_area_faces));
  if (mesh.indices.empty())
    throw InputError(fmt::format("{}: {}: the mesh has no faces (expected triangles or polygons)",
                                 where(o, o.file_location, "file"), o.file));
  return files.emplace(o.file, std::move(mesh)).first->second;
}

void add_objects(const Scenario& s, renderer::Scene& scene,
                 std::map<std::string, MeshData>* meshes) {
  if (s.objects.empty()) return;
  const renderer::GroundProbe probe(scene.ground.mesh);
  std::map<std::string, MeshData> local;
  std::map<std::string, MeshData>& files = meshes != nullptr ? *meshes : local;
  std::map<std::pair<std::string, bool>, std::uint32_t> prototype_of;
  std::map<std::string, std::shared_ptr<const renderer::ObjectTexture>> textures;
  std::vector<TakenGround> taken;
  for (std::size_t i = 0; i < s.objects.size(); ++i) {
    const ObjectSettings& o = s.objects[i];
    const MeshData& mesh = read_object_mesh(o, files);
    auto [it, fresh] = prototype_of.emplace(
        std::pair{o.file, o.z_up}, static_cast<std::uint32_t>(scene.object_prototypes.size()));
    if (fresh) scene.object_prototypes.push_back(to_prototype(mesh, o));
    const renderer::ObjectPrototype& proto = scene.object_prototypes[it->second];
    const ObjectSettings drawn = with_draws(o, i, s, proto, scene, probe, taken);
    const ObjectPlacement placed = place(proto, drawn, scene.origin, probe);
    renderer::ObjectInstance instance;
    instance.name = o.name;
    instance.prototype = it->second;
    instance.transform = placed.transform;
    instance.materials = object_materials(o, mesh, textures);
    scene.objects.push_back(std::move(instance));
    taken.push_back({placed.transform[9], placed.transform[10], placed.footprint_radius});
    clear_trees(scene, placed.transform[9], placed.transform[10],
                o.clear_radius.value_or(placed.footprint_radius + 1.0));
  }
  spdlog::info("{} objects of {} meshes placed", scene.objects.size(),
               scene.object_prototypes.size());
}

}  // namespace landsim::scenes::detail
