#pragma once
// What a built scene holds (`landsim info`): instances per species, unique variants,
// triangles stored and instanced, and an estimate of the memory rendering it takes.
#include <cstdint>
#include <map>
#include <string>

#include "renderer/scene.h"
#include "scenes/scenario.h"

namespace landsim::scenes {

struct SceneSummary {
  std::size_t instances = 0;
  std::map<std::string, std::size_t> instances_per_species;
  std::size_t unique_variants = 0;
  std::size_t triangles_stored = 0;     // ground + every prototype once
  std::size_t triangles_instanced = 0;  // ground + every instance's prototype
  std::size_t grass_tiles = 0;
  std::size_t memory_estimate_bytes = 0;
};

SceneSummary summarize(const Scenario& scenario, const renderer::Scene& scene);

}  // namespace landsim::scenes
