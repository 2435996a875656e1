#pragma once
// The memory a render of a scenario will take at its peak, estimated from counts that are
// cheap to get, before anything expensive is built (the memory budget, issue 27): the
// expected trees from each species' feature-map area and density (no tree is placed), the
// geometry of one generated variant per species, the grass tiles and the patches each view
// draws, Embree's bytes per primitive and per instance (renderer/acceleration/memory_model.h), and
// the film. docs/PERFORMANCE.md "Memory budget" says how each part is computed and how close the
// total comes to measured peaks.
#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "scenes/builder/variant_cache.h"
#include "scenes/scenario/scenario.h"

namespace landsim::scenes {

struct MemoryPart {
  std::string id;    // stable: "tree_instances", "tree_variants", ... (JSON keys)
  std::string name;  // for people: "tree instances (2194 trees)", ...
  std::size_t bytes = 0;
  std::string remedy;  // what would make it smaller, for the refusal message
};

struct MemoryEstimate {
  std::string scenario;           // its source, for messages
  std::size_t program_bytes = 0;  // this process before the scene: code and libraries
  std::vector<MemoryPart> parts;  // at the peak, largest first
  std::size_t total_bytes() const;

  // The counts behind it (`landsim info`).
  double instances = 0.0;  // expected: feature-map area x density
  std::map<std::string, double> instances_per_species;
  std::size_t unique_variants = 0;
  double triangles_stored = 0.0;     // ground + every variant once
  double triangles_instanced = 0.0;  // ground + every expected tree's variant
  std::size_t grass_tiles = 0;
  std::size_t grass_patches_drawn = 0;  // by the view that draws the most
};

// The estimate as `landsim info --json` and the Python module's `info` give it
// (docs/JSON.md "info").
nlohmann::json estimate_json(const Scenario& scenario, const MemoryEstimate& e);

// Loads the terrain and feature map and generates one variant per species; places nothing.
// The variants are left in `keep`, when given, for build_scene to reuse. `program`: the
// program's own size to count (an image set's later estimates take the one measured before
// its first scene: the process's size since then holds the freed scenes' memory the
// allocator keeps for the next); empty: the process's resident size now.
MemoryEstimate estimate_memory(const Scenario& scenario, VariantCache* keep = nullptr,
                               std::optional<std::size_t> program = std::nullopt);

struct MemoryBudget {
  std::size_t bytes = 0;
  std::string source;  // where it comes from, for messages
};

// The default budget: 80% of physical memory (or of the address-space limit, ulimit -v, if
// lower), shared by the `ranks_on_node` processes of an MPI job on this machine.
MemoryBudget default_memory_budget(int ranks_on_node = 1);

// InputError when the estimate exceeds `budget_bytes`: names the largest parts and what
// would bring each down. `budget_source` says where the budget came from (for the message).
void check_memory_budget(const MemoryEstimate& estimate, std::size_t budget_bytes,
                         const std::string& budget_source);

}  // namespace landsim::scenes
