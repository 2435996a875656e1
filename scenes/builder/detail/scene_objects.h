#pragma once
// [[objects]] into the scene (docs/OBJECTS.md): every mesh file read once (Assimp, through
// the meshes module) into a prototype, every object placed on the rendered ground as an
// instance of it with its own materials, and the trees within its clear radius removed.
#include <map>
#include <string>

#include "renderer/scene.h"
#include "scenes/builder/mesh_io.h"
#include "scenes/scenario/scenario.h"

namespace landsim::scenes::detail {

// The scene's ground mesh must be built. Throws InputError, located at the object's entry,
// for a mesh that cannot be read, has no faces or non-finite vertices, an override of a
// material the mesh lacks, or an object off the terrain or over a nodata hole.
// `meshes`, when given, holds files already read (the memory estimate's), used as they are.
void add_objects(const Scenario& s, renderer::Scene& scene,
                 std::map<std::string, MeshData>* meshes = nullptr);

// The mesh of `o` from `files`, read into it first when it is not there; InputError located
// at the object's `file` key when it cannot be read or has no faces.
const MeshData& read_object_mesh(const ObjectSettings& o, std::map<std::string, MeshData>& files);

}  // namespace landsim::scenes::detail
