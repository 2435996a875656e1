#pragma once
// Work the memory estimate does once and hands on to the scene builder: tree variants (the
// estimate generates one per species to size the rest) and the object meshes it reads to
// count them, so that neither is made a second time (render and info start sooner).
#include <compare>
#include <cstdint>
#include <map>
#include <string>

#include "renderer/scene.h"
#include "scenes/builder/mesh_io.h"

namespace landsim::scenes {

struct VariantKey {
  std::uint32_t species = 0;
  std::uint32_t variant = 0;
  double time = 0.0;  // the frame time the variant was generated for (wind sway)
  std::uint32_t phase_group = 0;
  auto operator<=>(const VariantKey&) const = default;
};

struct VariantCache {
  std::map<VariantKey, renderer::TreePrototype> trees;
  std::map<std::string, MeshData> meshes;  // by resolved file path ([[objects]] file)
  void clear() {
    trees.clear();
    meshes.clear();
  }
};

}  // namespace landsim::scenes
