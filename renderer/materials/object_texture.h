#pragma once
// An object's base-colour texture: an image (anything OpenImageIO reads; 8- and 16-bit
// images are sRGB-encoded as glTF and MTL files intend, float images linear) sampled at a
// mesh's texture coordinates, which Assimp gives with v up from the image's bottom row.
#include <memory>
#include <string>
#include <vector>

#include "core/vec3.h"
#include "renderer/materials/texture_image.h"

namespace landsim::renderer {

class ObjectTexture {
 public:
  explicit ObjectTexture(TextureImage image) : image_(std::move(image)) {}
  // Linear RGB, bilinear, repeating in both directions (glTF's default wrap).
  Vec3f colour(float u, float v) const;

 private:
  TextureImage image_;
};

// Throws InputError naming the file when it cannot be read.
std::shared_ptr<const ObjectTexture> load_object_texture(const std::string& path);

}  // namespace landsim::renderer
