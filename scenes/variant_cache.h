#pragma once
// Tree variants generated once and handed on: the memory estimate generates one variant per
// species to size the rest, and the scene builder takes those instead of generating them a
// second time (render and info start sooner).
#include <compare>
#include <cstdint>
#include <map>

#include "renderer/scene.h"

namespace landsim::scenes {

struct VariantKey {
  std::uint32_t species = 0;
  std::uint32_t variant = 0;
  double time = 0.0;  // the frame time the variant was generated for (wind sway)
  auto operator<=>(const VariantKey&) const = default;
};

using VariantCache = std::map<VariantKey, renderer::TreePrototype>;

}  // namespace landsim::scenes
