#pragma once
// An object's base-colour texture: an image (anything OpenImageIO reads; 8- and 16-bit
// images are sRGB-encoded as glTF and MTL files intend, float images linear) sampled at a
// mesh's texture coordinates, which Assimp gives with v up from the image's bottom row.
#include <memory>
#include <string>
#include <vector>

#include "core/vec3.h"

namespace landsim::renderer {

class ObjectTexture {
 public:
  ObjectTexture(int width, int height, std::vector<float> rgb);
  // Linear RGB, bilinear, repeating in both directions (glTF's default wrap).
  Vec3f colour(float u, float v) const;

 private:
  Vec3f texel(int x, int y) const;
  int width_, height_;
  std::vector<float> rgb_;  // linear, top row first
};

// Throws InputError naming the file when it cannot be read.
std::shared_ptr<const ObjectTexture> load_object_texture(const std::string& path);

}  // namespace landsim::renderer
