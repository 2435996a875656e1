// liblandsim_meshes.so: the mesh function table of scenes/builder/mesh_io.h on Assimp. Loaded by
// landsim the first time a scene object is read (core/module_loader.h).
#include "scenes/builder/mesh_io.h"

#include <assimp/BaseImporter.h>
#include <assimp/importerdesc.h>
#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <assimp/Importer.hpp>

#include <algorithm>
#include <cmath>
#include <exception>
#include <filesystem>
#include <functional>
#include <sstream>
#include <string>
#include <tuple>
#include <unordered_map>
#include <vector>

namespace landsim::scenes {
namespace {

struct PositionHash {
  std::size_t operator()(const std::tuple<float, float, float>& p) const {
    const auto bits = [](float f) { return std::hash<float>{}(f); };
    return bits(std::get<0>(p)) ^ (bits(std::get<1>(p)) * 0x9e3779b97f4a7c15ULL) ^
           (bits(std::get<2>(p)) * 0xc2b2ae3d27d4eb4fULL);
  }
};

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

// Corners sharing one position beyond which Assimp's smooth normals are not generated: it
// compares every pair of them (a 30,000-triangle fan took 4.7 s, 10^6 zero-area faces on
// three vertices never ended). Such meshes take flat normals, in linear time.
constexpr std::size_t kMaxSharedCorners = 256;

// The most corners of any mesh without normals that share one position.
std::size_t most_shared_corners(const aiScene& scene) {
  std::size_t most = 0;
  for (unsigned k = 0; k < scene.mNumMeshes; ++k) {
    const aiMesh& mesh = *scene.mMeshes[k];
    if (mesh.mNormals != nullptr) continue;
    std::unordered_map<std::tuple<float, float, float>, std::size_t, PositionHash> count;
    count.reserve(mesh.mNumVertices);
    for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
      const aiVector3D& p = mesh.mVertices[v];
      most = std::max(most, ++count[{p.x, p.y, p.z}]);
    }
  }
  return most;
}

// A triangle of zero area reflects nothing and has no normal: it is left out.
bool degenerate(const aiMesh& mesh, const aiFace& face) {
  const aiVector3D& a = mesh.mVertices[face.mIndices[0]];
  const aiVector3D e1 = mesh.mVertices[face.mIndices[1]] - a;
  const aiVector3D e2 = mesh.mVertices[face.mIndices[2]] - a;
  return (e1 ^ e2).SquareLength() == 0.0f;
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
    if (degenerate(mesh, face)) {
      ++out.zero_area_faces;
      continue;
    }
    out.indices.insert(out.indices.end(), {first + face.mIndices[0], first + face.mIndices[1],
                                           first + face.mIndices[2]});
    out.triangle_material.push_back(mesh.mMaterialIndex);
  }
}

// When the importer for a file's extension declines it, Assimp tries every other importer it
// has on the content: a ".gltf" that was no JSON reached its OpenGEX reader, which read past
// its buffer (mesh_fuzz, session 18). landsim reads OBJ, PLY and glTF/GLB (docs/OBJECTS.md):
// every other importer is unregistered, and deleted (the Importer no longer owns it).
void keep_only_mesh_formats(Assimp::Importer& importer) {
  std::vector<Assimp::BaseImporter*> others;
  for (std::size_t i = 0; i < importer.GetImporterCount(); ++i) {
    const aiImporterDesc* desc = importer.GetImporterInfo(i);
    std::istringstream extensions(
        desc != nullptr && desc->mFileExtensions != nullptr ? desc->mFileExtensions : "");
    bool ours = false;
    for (std::string e; extensions >> e;)
      ours = ours || e == "obj" || e == "ply" || e == "gltf" || e == "glb";
    if (!ours) others.push_back(importer.GetImporter(i));
  }
  for (Assimp::BaseImporter* other : others)
    if (importer.UnregisterLoader(other) == aiReturn_SUCCESS) delete other;
}

bool read(const std::string& path, MeshData& mesh, std::string& error) {
  try {
    Assimp::Importer importer;
    keep_only_mesh_formats(importer);
    importer.SetPropertyFloat(AI_CONFIG_PP_GSN_MAX_SMOOTHING_ANGLE, kSmoothingAngleDeg);
    // Points and lines are dropped; node transforms are applied (glTF scenes are trees of
    // nodes); validation refuses broken structures.
    importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE,
                                aiPrimitiveType_POINT | aiPrimitiveType_LINE);
    const unsigned flags = aiProcess_Triangulate | aiProcess_PreTransformVertices |
                           aiProcess_SortByPType | aiProcess_ValidateDataStructure;
    const aiScene* scene = importer.ReadFile(path, flags);
    if (scene != nullptr) {
      // Normals the file lacks: smooth ones unless too many corners share a position.
      const bool smooth = most_shared_corners(*scene) <= kMaxSharedCorners;
      scene =
          importer.ApplyPostProcessing(smooth ? aiProcess_GenSmoothNormals : aiProcess_GenNormals);
    }
    if (scene == nullptr) {
      error = importer.GetErrorString();
      // Assimp's validation speaks of its own structures; a user's file simply has no mesh.
      if (error.find("mNumMeshes is 0") != std::string::npos ||
          error.find("contains no faces") != std::string::npos)
        error = "it holds no faces (expected triangles or polygons)";
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
