#include "scenes/builder/mesh_io.h"

#include "core/module_loader.h"

namespace landsim::scenes {

const MeshIo& mesh_io() { return module_table<MeshIo>("meshes", kMeshIoSymbol); }

}  // namespace landsim::scenes
