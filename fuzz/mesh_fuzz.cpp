// A scene object's mesh file (docs/OBJECTS.md) through the header checks and the meshes
// module (Assimp): OBJ, PLY, glTF or GLB, chosen by the input's first byte.
#include "fuzz/fuzz_input.h"
#include "scenes/builder/detail/mesh_file_check.h"
#include "scenes/builder/mesh_io.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  static const char* const kNames[] = {"model.obj", "model.ply", "model.gltf", "model.glb"};
  const auto file = landsim::fuzz::input_file(data + 1, size - 1, kNames[data[0] % 4]);
  return landsim::fuzz::refused_or_read([&] {
    landsim::scenes::detail::check_mesh_file(file.string(), "fuzz");
    landsim::scenes::MeshData mesh;
    std::string error;
    landsim::scenes::mesh_io().read(file.string(), mesh, error);  // false: refused, said
  });
}
