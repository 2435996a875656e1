#pragma once
// The camera of a user's own POV-Ray scene, read from its `camera { }` block, as a landsim
// view: for `landsim crosscheck --pov FILE.pov` (docs/CROSSCHECK.md "Against a POV-Ray
// scene"). The file's coordinates are taken in the POV-Ray export's frame (x east, y up,
// z north, metres from the scene origin). Only what a landsim view can reproduce is
// accepted: a perspective camera, upright (sky along +y), left-handed as POV-Ray's default,
// with literal vectors and numbers (unit vectors x, y, z, pi, image_width, image_height,
// arithmetic and a few functions allowed); anything else is refused with the file and line.
#include <filesystem>
#include <string>

#include "core/vec3.h"
#include "renderer/scene.h"

namespace landsim::exporters {

struct PovCamera {
  Vec3 location;  // POV-Ray's frame
  Vec3 look_at;   // POV-Ray's frame; location + direction when the block has no look_at
  double horizontal_fov_deg = 0.0;
  double aspect = 0.0;  // |right| / |up|
  std::string where;    // "file:line" of the camera block, for messages
};

// Reads the one camera of `file` (image_width and image_height are what its expressions may
// use). Throws InputError naming the file and line when there is no camera, more than one,
// or one a landsim view cannot match.
PovCamera read_pov_camera(const std::filesystem::path& file, int image_width, int image_height);

// Parses `text` as if it were the file `name`.
PovCamera parse_pov_camera(const std::string& text, const std::string& name, int image_width,
                           int image_height);

// `base` (its name and size) looking as `camera` does, in the scene frame. Throws InputError
// when the camera's aspect differs from base's width / height by more than 1%.
renderer::View pov_camera_view(const PovCamera& camera, const renderer::View& base);

}  // namespace landsim::exporters
