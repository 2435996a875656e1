#pragma once
// What a mesh file says of its own size, checked against the file before Assimp reads it:
// a garbage GLB whose header claims a 2 GB chunk was allocated and filled, a PLY claiming
// 2^31 faces ended in std::bad_alloc, and a glTF buffer's uri outside the model's folder was
// read (/etc/passwd as vertex data). Each is refused with the file, the field and what the
// file holds, as an InputError; `where` prefixes the message (the scenario's file:line).
#include <string>

namespace landsim::scenes::detail {

void check_mesh_file(const std::string& path, const std::string& where);

}  // namespace landsim::scenes::detail
