#include "exporters/pov_export.h"

#include "exporters/pov_view.h"

#include <fmt/format.h>
#include <fmt/os.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numbers>

#include "core/atomic_file.h"
#include "renderer/materials/grass_patch.h"
#include "renderer/output/exposure.h"
#include "renderer/spectra/colour_matching.h"
#include "renderer/transport/bsdf.h"

namespace landsim::exporters {
namespace {

// landsim (x east, y north, z up) -> POV-Ray (x, y up, z).
std::string pov(const Vec3& v) { return fmt::format("<{:.6f}, {:.6f}, {:.6f}>", v.x, v.z, v.y); }
std::string pov(const Vec3f& v) { return fmt::format("<{:.6g}, {:.6g}, {:.6g}>", v.x, v.z, v.y); }
std::string rgb(const Vec3f& c) {
  return fmt::format("rgb <{:.6g}, {:.6g}, {:.6g}>", c.x, c.y, c.z);
}
// A light's colour, in landsim's photometric units, times the file's exposure.
std::string light(const Vec3f& c) { return rgb(c) + " * LS_Exposure"; }
std::string colour_vector(const Vec3f& c) {
  return fmt::format("<{:.6g}, {:.6g}, {:.6g}>", c.x, c.y, c.z);
}

// Per-vertex textures of a mesh2: its texture_list entries and each vertex's entry, which
// POV-Ray interpolates across a triangle.
struct VertexTextures {
  std::vector<std::string> list;
  std::vector<std::size_t> of_vertex;  // by vertex index
};

void write_mesh2(fmt::ostream& out, const std::string& name, const std::vector<Vec3f>& vertices,
                 const std::vector<Vec3f>& normals, const std::vector<std::uint32_t>& indices,
                 const VertexTextures* textures = nullptr) {
  out.print("#declare {} = mesh2 {{\n  vertex_vectors {{ {}", name, vertices.size());
  for (const Vec3f& v : vertices) out.print(",\n    {}", pov(v));
  out.print("\n  }}\n  normal_vectors {{ {}", normals.size());
  for (const Vec3f& n : normals) out.print(",\n    {}", pov(n));
  if (textures != nullptr) {
    out.print("\n  }}\n  texture_list {{ {}", textures->list.size());
    for (const std::string& t : textures->list) out.print(",\n    {}", t);
  }
  out.print("\n  }}\n  face_indices {{ {}", indices.size() / 3);
  for (std::size_t i = 0; i + 2 < indices.size(); i += 3) {
    out.print(",\n    <{}, {}, {}>", indices[i], indices[i + 1], indices[i + 2]);
    if (textures != nullptr)
      out.print(", {}, {}, {}", textures->of_vertex[indices[i]],
                textures->of_vertex[indices[i + 1]], textures->of_vertex[indices[i + 2]]);
  }
  out.print("\n  }}\n}}\n");
}

// The ground of one material with its shading variation as vertex colours: each vertex
// takes shade_ground's albedo there (image textures left out: POV-Ray has no three-sided
// projection, and a vertex would alias the image), quantised into a palette of LS_Texture
// entries.
VertexTextures ground_textures(const renderer::Scene& scene, int id,
                               const std::vector<std::uint32_t>& indices) {
  const terrain::GroundMesh& m = scene.ground.mesh;
  constexpr std::size_t kUnset = static_cast<std::size_t>(-1);
  VertexTextures out;
  out.of_vertex.assign(m.vertices.size(), kUnset);
  std::map<std::array<int, 3>, std::size_t> palette;
  for (std::uint32_t v : indices) {
    if (out.of_vertex[v] != kUnset) continue;
    const renderer::ShadedGround g =
        renderer::shade_ground(scene.ground, id, Vec3(m.vertices[v]) + scene.origin,
                               normalize(Vec3(m.normals[v])), scene.sun.direction, false);
    const std::array<int, 3> q{static_cast<int>(std::lround(g.albedo.x * 1024.0f)),
                               static_cast<int>(std::lround(g.albedo.y * 1024.0f)),
                               static_cast<int>(std::lround(g.albedo.z * 1024.0f))};
    const auto [it, added] = palette.try_emplace(q, out.list.size());
    if (added)
      out.list.push_back(fmt::format("LS_Texture(<1, 0, 0>, <{:.6g}, {:.6g}, {:.6g}>)",
                                     q[0] / 1024.0, q[1] / 1024.0, q[2] / 1024.0));
    out.of_vertex[v] = it->second;
  }
  return out;
}

// A grass patch as the renderer makes it.
renderer::GrassBlades grass_patch(const renderer::Scene& scene, int type, int variant, int level) {
  return renderer::make_grass_patch(scene.grass.types[static_cast<std::size_t>(type)],
                                    scene.grass.tile, level,
                                    renderer::grass_patch_seed(type, variant));
}

// POV-Ray's matrix for a landsim transform with axis columns x, y, z and translation t:
// rows are where POV-Ray's axes go, POV-Ray's y being landsim's z.
std::string pov_matrix(const std::array<float, 12>& m) {
  const Vec3f x{m[0], m[1], m[2]}, y{m[3], m[4], m[5]}, z{m[6], m[7], m[8]}, t{m[9], m[10], m[11]};
  const auto row = [](const Vec3f& v) {
    return fmt::format("{:.9g}, {:.9g}, {:.9g}", v.x, v.z, v.y);
  };
  return fmt::format("matrix <{}, {}, {}, {}>", row(x), row(z), row(y), row(t));
}

// POV-Ray's matrix of a tree instance: rotation about landsim's z (POV's y), uniform scale,
// translation; rows are where the x, y and z axes go, then the translation.
std::string instance_matrix(const renderer::TreeInstance& t) {
  const double c = std::cos(t.rotation) * t.scale, s = std::sin(t.rotation) * t.scale, k = t.scale;
  if (t.leans()) {  // a leaning tree: the general matrix (landsim's axes as columns)
    const auto f = [](const Vec3& v) { return Vec3f(v); };
    const Vec3f x = f(t.apply_lean({c, s, 0.0})), y = f(t.apply_lean({-s, c, 0.0})),
                z = f(t.apply_lean({0.0, 0.0, k}));
    return pov_matrix({x.x, x.y, x.z, y.x, y.y, y.z, z.x, z.y, z.z,
                       static_cast<float>(t.position.x), static_cast<float>(t.position.y),
                       static_cast<float>(t.position.z)});
  }
  return fmt::format(
      "matrix <{:.9g}, 0, {:.9g}, 0, {:.9g}, 0, {:.9g}, 0, {:.9g}, {:.6f}, {:.6f}, {:.6f}>", c, s,
      k, -s, c, t.position.x, t.position.z, t.position.y);
}

// A grass patch's blades as ribbons (two triangles per segment, as wide as the blade) in
// POV-Ray axes; landsim traces them as round curves of that width.
void write_grass_patch(fmt::ostream& out, const std::string& name, const renderer::GrassBlades& b) {
  std::vector<Vec3f> vertices, normals;
  std::vector<std::uint32_t> indices;
  for (std::uint32_t first : b.first) {
    const auto at = [&](std::uint32_t k) {
      return Vec3f{b.points[4 * k], b.points[4 * k + 1], b.points[4 * k + 2]};
    };
    const Vec3f p0 = at(first), p1 = at(first + 1);
    const float r0 = b.points[4 * first + 3], r1 = b.points[4 * (first + 1) + 3];
    const auto base = static_cast<std::uint32_t>(vertices.size());
    vertices.insert(vertices.end(), {p0 - Vec3f{r0, 0, 0}, p0 + Vec3f{r0, 0, 0},
                                     p1 + Vec3f{r1, 0, 0}, p1 - Vec3f{r1, 0, 0}});
    normals.insert(normals.end(), 4, Vec3f{0, 1, 0});
    indices.insert(indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
  }
  write_mesh2(out, name, vertices, normals, indices);
}

// Ground triangles grouped by material id (0: the terrain's own albedo).
std::map<int, std::vector<std::uint32_t>> ground_by_material(const renderer::Ground& ground) {
  std::map<int, std::vector<std::uint32_t>> groups;
  const std::vector<std::uint32_t>& idx = ground.mesh.indices;
  for (std::size_t t = 0; t < ground.mesh.triangle_count(); ++t) {
    const int id = ground.material_id(t);
    groups[id].insert(groups[id].end(), idx.begin() + static_cast<std::ptrdiff_t>(3 * t),
                      idx.begin() + static_cast<std::ptrdiff_t>(3 * t + 3));
  }
  return groups;
}

// Leaf triangles grouped by vigour level, for leaves with graded vigour (else none): the
// renderer colours each leaf by its level, so the export draws each level in its colour.
std::map<int, std::vector<std::uint32_t>> leaves_by_vigour(const trees::GroupGeometry& leaves) {
  std::map<int, std::vector<std::uint32_t>> groups;
  if (leaves.item_vigour.empty()) return groups;
  const std::vector<std::uint32_t>& idx = leaves.triangles.indices;
  for (std::uint32_t t = 0; t < leaves.triangles.triangle_count(); ++t) {
    const int level =
        static_cast<int>(std::lround(leaves.vigour_of_triangle(t) * (trees::kVigourLevels - 1)));
    groups[level].insert(groups[level].end(), idx.begin() + static_cast<std::ptrdiff_t>(3 * t),
                         idx.begin() + static_cast<std::ptrdiff_t>(3 * t + 3));
  }
  return groups;
}

// An object prototype's triangles grouped by mesh material.
std::map<std::uint32_t, std::vector<std::uint32_t>> object_by_material(
    const renderer::ObjectPrototype& p) {
  std::map<std::uint32_t, std::vector<std::uint32_t>> groups;
  for (std::size_t t = 0; t < p.triangle_count(); ++t) {
    auto& g = groups[p.triangle_material[t]];
    g.insert(g.end(), p.indices.begin() + static_cast<std::ptrdiff_t>(3 * t),
             p.indices.begin() + static_cast<std::ptrdiff_t>(3 * t + 3));
  }
  return groups;
}

// Scene objects: each of an object's materials as POV-Ray's nearest finish, a diffuse base
// colour (textures left out: their mean is not the factor) with a Phong-like specular
// highlight of the coat's reflectance at normal incidence and a roughness of GGX alpha^2;
// the mask draws them yellow.
void write_objects(fmt::ostream& out, const renderer::Scene& scene) {
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    const renderer::ObjectInstance& o = scene.objects[i];
    out.print("// object {}\nunion {{\n", sanitize_for_pov(o.name));
    for (const auto& [m, indices] : object_by_material(scene.object_prototypes[o.prototype])) {
      const renderer::ObjectMaterial& mat = o.materials[m];
      const renderer::ObjectLobes lobes = renderer::object_lobes(mat, mat.base_colour);
      out.print("  object {{ LS_Object_{}_{} LS_ObjectTexture({}, {:.6g}, {:.6g}) }}\n",
                o.prototype, m, colour_vector(lobes.diffuse), max_component(lobes.specular),
                lobes.alpha * lobes.alpha);
    }
    std::array<float, 12> m{};
    for (std::size_t k = 0; k < 12; ++k) m[k] = static_cast<float>(o.transform[k]);
    out.print("  {}\n}}\n", pov_matrix(m));
  }
}

}  // namespace

double pov_exposure_gain(const renderer::Scene& scene, const renderer::SkyModel& sky) {
  if (scene.settings.exposure_ev100) return renderer::preview_gain(*scene.settings.exposure_ev100);
  const Vec3f sun =
      scene.sun.irradiance * static_cast<float>(std::max(0.0, normalize(scene.sun.direction).z));
  const double e = renderer::rec709_luminance(Vec3(sun + sky.horizontal_irradiance()));
  return e > 0.0 ? std::numbers::pi / e : 1.0;
}

std::string sanitize_for_pov(const std::string& text) {
  std::string out;
  for (const char ch : text) {
    const auto c = static_cast<unsigned char>(ch);
    out += (std::isalnum(c) || ch == ' ' || ch == '_' || ch == '-' || ch == '.') ? ch : '_';
  }
  return out;
}

void export_pov(const renderer::Scene& scene, const renderer::View& view,
                const std::filesystem::path& dir, const PovExportOptions& o) {
  std::filesystem::create_directories(dir);
  for (std::uint8_t id = 0; id < renderer::kGroundMaterials; ++id)
    if (scene.ground.brdf_of(id) != nullptr) {
      spdlog::warn(
          "export: POV-Ray has no RPV or Ross-Li reflection; the ground is exported Lambertian "
          "at each material's reflectance (the model's isotropic parameter; docs/GROUND.md)");
      break;
    }
  {
    AtomicFile inc(dir / "meshes.inc");
    {
      auto out = fmt::output_file(inc.temp_path().string());
      out.print("// landsim tree prototypes, POV-Ray axes (y up)\n");
      // The ground, one mesh per ground material (soil, rock, water, road, under grass).
      for (const auto& [id, indices] : ground_by_material(scene.ground)) {
        const VertexTextures colours = ground_textures(scene, id, indices);
        write_mesh2(out, fmt::format("LS_Ground_{}", id), scene.ground.mesh.vertices,
                    scene.ground.mesh.normals, indices, &colours);
      }
      for (std::size_t p = 0; p < scene.prototypes.size(); ++p) {
        const trees::TreeGeometry& g = scene.prototypes[p].geometry;
        for (int k = 0; k < trees::kGroupCount; ++k) {
          const trees::GroupGeometry& group = g.groups[static_cast<std::size_t>(k)];
          const trees::TriangleSet& t = group.triangles;
          if (!t.indices.empty() && group.item_vigour.empty())
            write_mesh2(out, fmt::format("LS_Proto_{}_{}", p, k), t.vertices, t.normals, t.indices);
        }
        // An abstract canopy's leaves are discs (TreePrototype::leaf_discs): POV-Ray's own.
        if (scene.prototypes[p].leaf_discs) {
          const trees::PointSet& d = g.group(trees::Group::leaves).points;
          out.print("#declare LS_Proto_{}_discs = union {{\n", p);
          for (std::size_t i = 0; i < d.point_count(); ++i)
            out.print("  disc {{ {}, {}, {:.6g} }}\n", pov(d.centres[i]), pov(d.normals[i]),
                      d.radii[i]);
          out.print("}}\n");
        }
        // Leaves of graded vigour: one mesh per level, each drawn in its own colour.
        for (const auto& [level, indices] : leaves_by_vigour(g.group(trees::Group::leaves)))
          write_mesh2(out, fmt::format("LS_Proto_{}_4_{}", p, level),
                      g.group(trees::Group::leaves).triangles.vertices,
                      g.group(trees::Group::leaves).triangles.normals, indices);
      }
      for (std::size_t p = 0; p < scene.object_prototypes.size(); ++p) {
        const renderer::ObjectPrototype& proto = scene.object_prototypes[p];
        for (const auto& [m, indices] : object_by_material(proto))
          write_mesh2(out, fmt::format("LS_Object_{}_{}", p, m), proto.vertices, proto.normals,
                      indices);
      }
      if (scene.grass.cols > 0) {
        for (int t = 0; t < 3; ++t)
          for (int variant = 0; variant < renderer::kGrassVariants; ++variant)
            for (int level = 0; level < renderer::kGrassLevels; ++level)
              write_grass_patch(out, fmt::format("LS_Grass_{}_{}_{}", t, variant, level),
                                grass_patch(scene, t, variant, level));
      }
    }
    inc.commit();
  }
  AtomicFile file(dir / "scene.pov");
  {
    auto out = fmt::output_file(file.temp_path().string());
    const PovView camera = pov_view(view);
    out.print("// landsim export: view {}\n#version 3.7;\n", sanitize_for_pov(view.name));
    for (const std::string& u : camera.unshown) {
      out.print("// not shown by POV-Ray's camera: {}\n", u);
      spdlog::warn("export-pov: view {}: not shown by POV-Ray's camera: {}", view.name, u);
    }
    out.print("#ifndef (LS_Mask) #declare LS_Mask = 0; #end\n");
    // Lights are in cd/m2 and lux; POV-Ray writes what it computes, so an 8-bit image needs
    // the exposure (LS_Exposure=1 on the command line keeps the photometric values, for EXR).
    out.print("#ifndef (LS_Exposure) #declare LS_Exposure = {:.6g}; #end\n", o.exposure_gain);
    out.print("global_settings {{ assumed_gamma 1.0 max_trace_level 5\n");
    out.print("  #if (LS_Mask) ambient_light rgb 1 #else ambient_light {} #end }}\n",
              light(o.ambient_irradiance / std::numbers::pi_v<float>));
    out.print(
        "#macro LS_Texture(Class, Albedo)\n  #if (LS_Mask) texture {{ pigment {{ rgb Class }} "
        "finish {{ ambient 1 diffuse 0 }} }}\n"
        "  #else texture {{ pigment {{ rgb Albedo }} finish {{ ambient 1 diffuse 1 }} }} "
        "#end\n#end\n");
    out.print(
        "#macro LS_ObjectTexture(Albedo, Specular, Roughness)\n  #if (LS_Mask) texture {{ pigment "
        "{{ rgb <1, 1, 0> }} finish {{ ambient 1 diffuse 0 }} }}\n"
        "  #else texture {{ pigment {{ rgb Albedo }} finish {{ ambient 1 diffuse 1 specular "
        "Specular roughness Roughness }} }} #end\n#end\n");
    out.print("#include \"meshes.inc\"\n");  // its ground meshes use LS_Texture
    out.print("{}\n", camera.camera);
    const Vec3 sun = normalize(scene.sun.direction) * 1e7;
    out.print("#if (!LS_Mask)\nlight_source {{ {} color {} parallel point_at <0, 0, 0> }}\n",
              pov(sun), light(scene.sun.irradiance / std::numbers::pi_v<float>));
    out.print("sky_sphere {{ pigment {{ gradient y color_map {{ [0 {}] [1 {}] }} }} }}\n",
              light(o.sky_horizon), light(o.sky_zenith));
    if (scene.haze.enabled) {
      out.print("fog {{ fog_type 1 distance {:.6g} color {} }}\n", scene.haze.visibility / 3.912,
                light(o.fog_colour));
    }
    out.print("#else\nbackground {{ rgb 0 }}\n#end\n");
    // The ground's colours are its vertices' (meshes.inc).
    for (const auto& [id, indices] : ground_by_material(scene.ground))
      out.print("object {{ LS_Ground_{} }}\n", id);
    for (std::size_t p = 0; p < scene.prototypes.size(); ++p) {
      const renderer::TreePrototype& proto = scene.prototypes[p];
      out.print("#declare LS_Tree_{} = union {{\n", p);
      if (proto.leaf_discs)
        out.print("  object {{ LS_Proto_{}_discs LS_Texture(<0, 0, 1>, {}) }}\n", p,
                  colour_vector(proto.leaf_reflectance));
      for (const auto& [level, indices] :
           leaves_by_vigour(proto.geometry.group(trees::Group::leaves)))
        out.print(
            "  object {{ LS_Proto_{}_4_{} LS_Texture(<0, 0, 1>, {}) }}\n", p, level,
            colour_vector(proto.leaf_reflectance *
                          proto.leaf_tint(static_cast<float>(level) / (trees::kVigourLevels - 1))));
      for (int k = 0; k < trees::kGroupCount; ++k) {
        if (proto.geometry.groups[static_cast<std::size_t>(k)].triangles.indices.empty()) continue;
        const bool leaf = k == static_cast<int>(trees::Group::leaves);
        if (leaf && !proto.geometry.group(trees::Group::leaves).item_vigour.empty()) continue;
        out.print("  object {{ LS_Proto_{}_{} LS_Texture({}, {}) }}\n", p, k,
                  leaf ? "<0, 0, 1>" : "<0, 1, 0>",
                  colour_vector(leaf ? proto.leaf_reflectance : proto.bark_albedo));
      }
      out.print("}}\n");
    }
    for (const renderer::TreeInstance& t : scene.instances) {
      out.print("object {{ LS_Tree_{} {} }}\n", t.prototype, instance_matrix(t));
    }
    write_objects(out, scene);
    // Grass: the same patches at the same levels landsim draws for this view without
    // degradation's blending (POV-Ray has no stochastic levels); the mask counts grass as
    // ground, as landsim's comparison does.
    // A patch some of whose blades the grass mask drops (a field's edge, a road) is written
    // for its tile with the blades landsim keeps.
    std::map<std::array<int, 3>, renderer::GrassBlades> patches;  // made once each
    renderer::for_each_grass_patch(
        scene.grass, view, false, [&](const renderer::GrassPatchPlacement& p) {
          const renderer::GrassType& g = scene.grass.types[static_cast<std::size_t>(p.type - 1)];
          auto [it, added] = patches.try_emplace({p.type - 1, p.variant, p.level});
          if (added) it->second = grass_patch(scene, p.type - 1, p.variant, p.level);
          const renderer::GrassBlades& patch = it->second;
          if (patch.first.empty()) return;
          std::string name = fmt::format("LS_Grass_{}_{}_{}", p.type - 1, p.variant, p.level);
          if (!renderer::grass_tile_whole(scene.grass.mask, p.frame, scene.grass.tile, p.type)) {
            const renderer::GrassBlades kept =
                renderer::kept_blades(patch, p.frame, scene.grass.mask, p.type);
            if (kept.first.empty()) return;
            if (kept.first.size() != patch.first.size()) {
              name = fmt::format("LS_GrassTile_{}_{}", p.tile, p.level);
              write_grass_patch(out, name, kept);
            }
          }
          out.print("object {{ {} LS_Texture(<1, 0, 0>, {}) {} }}\n", name,
                    colour_vector(g.reflectance), pov_matrix(p.frame));
        });
  }
  file.commit();
}

}  // namespace landsim::exporters
