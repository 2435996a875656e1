#pragma once
// Mesh files for scene objects (OBJ with its MTL, PLY, glTF 2.0 / GLB, and whatever else
// Assimp reads) through a module of their own (liblandsim_meshes.so, source in
// modules/meshes/), loaded the first time an object is read (core/module_loader.h). This is
// the module's function table: plain arrays out, in the file's own units and axes.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace landsim::scenes {

// A mesh material as the file states it (glTF's metallic-roughness model; an MTL's Kd and
// Ns are translated to it by the module).
struct MeshMaterial {
  std::string name;
  float base_colour[3] = {0.8f, 0.8f, 0.8f};  // linear RGB
  float roughness = 0.5f;                     // perceptual (GGX alpha = roughness^2)
  float metallic = 0.0f;
  std::string texture;            // base-colour image, absolute path; empty: none
  bool embedded_texture = false;  // the file embeds a texture (not read: see docs/OBJECTS.md)
};

// Every mesh of the file, its node transforms applied, triangulated, in one list.
struct MeshData {
  std::vector<float> positions;                  // x, y, z per vertex
  std::vector<float> normals;                    // x, y, z per vertex (the file's, or generated)
  std::vector<float> uvs;                        // u, v per vertex; empty when the file has none
  std::vector<std::uint32_t> indices;            // three per triangle
  std::vector<std::uint32_t> triangle_material;  // per triangle, into `materials`
  std::vector<MeshMaterial> materials;
  std::size_t zero_area_faces = 0;  // triangles of zero area, left out (they reflect nothing)
};

struct MeshIo {
  // Reads `path`; false with Assimp's message in `error`.
  bool (*read)(const std::string& path, MeshData& mesh, std::string& error);
};

// The module's table, loaded on first use (ModuleError when the module is missing).
const MeshIo& mesh_io();

// The symbol liblandsim_meshes.so exports: `const MeshIo* landsim_mesh_io()`.
inline constexpr const char* kMeshIoSymbol = "landsim_mesh_io";

}  // namespace landsim::scenes
