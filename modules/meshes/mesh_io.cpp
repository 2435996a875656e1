// liblandsim_meshes.so: the mesh function table of scenes/mesh_io.h on Assimp. Loaded by
// landsim the first time a scene object is read (core/module_loader.h).
#include "scenes/mesh_io.h"

#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <assimp/Importer.hpp>

#include <algorithm>
#include <cmath>
#include <exception>
#include <filesystem>

namespace landsim::scenes {
namespace {

// Normals the file lacks are generated smooth across edges sharper than this only, so that
// a box stays a box and a wheel stays round.
constexpr float kSmoothingAngleDeg = 35.0f;

MeshMaterial read_material(const aiMaterial& m, const std::filesystem::path& dir) {
  MeshMaterial out;
  aiString name;
  if (m.Get(AI_MATKEY_NAME, name) == AI_SUCCESS) out.name = name.C_Str();
  aiColor4D c;
  // glTF's base colour; an MTL's diffuse colour (Kd) otherwise.
  if (m.Get(AI_MATKEY_BASE_COLOR, c) == AI_SUCCESS ||
      m.Get(AI_MATKEY_COLOR_DIFFUSE, c) == AI_SUCCESS) {
    out.base_colour[0] = c.r;
    out.base_colour[1] = c.g;
    out.base_colour[2] = c.b;
  }
  float value = 0.0f;
  if (m.Get(AI_MATKEY_ROUGHNESS_FACTOR, value) == AI_SUCCESS) {
    out.roughness = value;
  } else if (m.Get(AI_MATKEY_SHININESS, value) == AI_SUCCESS && value > 0.0f) {
    // A Phong exponent (MTL Ns) as the GGX alpha of the same highlight width,
    // alpha = sqrt(2 / (Ns + 2)) (Walter et al. 2007), and perceptual roughness = sqrt(alpha).
    out.roughness = std::sqrt(std::sqrt(2.0f / (value + 2.0f)));
  }
  if (m.Get(AI_MATKEY_METALLIC_FACTOR, value) == AI_SUCCESS) out.metallic = value;
  out.roughness = std::clamp(out.roughness, 0.0f, 1.0f);
  out.metallic = std::clamp(out.metallic, 0.0f, 1.0f);
  aiString texture;
  if (m.GetTexture(aiTextureType_BASE_COLOR, 0, &texture) == AI_SUCCESS ||
      m.GetTexture(aiTextureType_DIFFUSE, 0, &texture) == AI_SUCCESS) {
    const std::string t = texture.C_Str();
    if (!t.empty() && t[0] == '*') {
      out.embedded_texture = true;
    } else if (!t.empty()) {
      std::string file = t;
      std::replace(file.begin(), file.end(), '\\', '/');
      out.texture = (dir / file).lexically_normal().string();
    }
  }
  return out;
}

void append_mesh(const aiMesh& mesh, MeshData& out) {
  const auto first = static_cast<std::uint32_t>(out.positions.size() / 3);
  for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
    const aiVector3D& p = mesh.mVertices[v];
    out.positions.insert(out.positions.end(), {p.x, p.y, p.z});
    const aiVector3D n = mesh.mNormals != nullptr ? mesh.mNormals[v] : aiVector3D(0, 0, 0);
    out.normals.insert(out.normals.end(), {n.x, n.y, n.z});
    const aiVector3D t = mesh.HasTextureCoords(0) ? mesh.mTextureCoords[0][v] : aiVector3D(0, 0, 0);
    out.uvs.insert(out.uvs.end(), {t.x, t.y});
  }
  for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
    const aiFace& face = mesh.mFaces[f];
    if (face.mNumIndices != 3) continue;  // points and lines: not surfaces
    out.indices.insert(out.indices.end(), {first + face.mIndices[0], first + face.mIndices[1],
                                           first + face.mIndices[2]});
    out.triangle_material.push_back(mesh.mMaterialIndex);
  }
}

bool read(const std::string& path, MeshData& mesh, std::string& error) {
  try {
    Assimp::Importer importer;
    importer.SetPropertyFloat(AI_CONFIG_PP_GSN_MAX_SMOOTHING_ANGLE, kSmoothingAngleDeg);
    // Points and lines are dropped; node transforms are applied (glTF scenes are trees of
    // nodes); validation refuses broken structures.
    importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE,
                                aiPrimitiveType_POINT | aiPrimitiveType_LINE);
    const unsigned flags = aiProcess_Triangulate | aiProcess_GenSmoothNormals |
                           aiProcess_PreTransformVertices | aiProcess_SortByPType |
                           aiProcess_ValidateDataStructure;
    const aiScene* scene = importer.ReadFile(path, flags);
    if (scene == nullptr) {
      error = importer.GetErrorString();
      return false;
    }
    mesh = MeshData{};
    const std::filesystem::path dir = std::filesystem::path(path).parent_path();
    for (unsigned m = 0; m < scene->mNumMaterials; ++m)
      mesh.materials.push_back(read_material(*scene->mMaterials[m], dir));
    if (mesh.materials.empty()) mesh.materials.emplace_back();
    bool any_uvs = false;
    for (unsigned k = 0; k < scene->mNumMeshes; ++k) {
      append_mesh(*scene->mMeshes[k], mesh);
      any_uvs = any_uvs || scene->mMeshes[k]->HasTextureCoords(0);
    }
    if (!any_uvs) mesh.uvs.clear();
    for (std::uint32_t& m : mesh.triangle_material)
      m = std::min<std::uint32_t>(m, static_cast<std::uint32_t>(mesh.materials.size() - 1));
    return true;
  } catch (const std::exception& e) {
    error = e.what();
    return false;
  }
}

const MeshIo kTable{&read};

}  // namespace
}  // namespace landsim::scenes

extern "C" __attribute__((visibility("default"))) const landsim::scenes::MeshIo* landsim_mesh_io() {
  return &landsim::scenes::kTable;
}
