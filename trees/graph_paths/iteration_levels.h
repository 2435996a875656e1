#pragma once
// The iterated levels of Xu & Mould 2012 (section 3.2) and their per-level settings (the
// paper's Table 2 gives each level its own subgraph shape, endpoint count, rotation of v_g
// and, section 3.1, its own thickness exponent z). `[iteration]` holds the defaults; each
// `[[iteration.level]]` row overrides them for one level, in order.
#include <optional>
#include <vector>

#include "core/vec3.h"

namespace landsim::trees::graph_paths {

// Where a level's subgraphs point before the rotation: along v_g (from the previous root to
// the endpoint), or straight down or up (Table 2, tree c: "v_g of level 2 are oriented in the
// negative vertical direction").
enum class Orientation { along, down, up };

// One row of the table: only the settings it names differ from `[iteration]`'s.
struct LevelSettings {
  std::optional<double> radius;  // metres
  std::optional<double> half_angle;
  std::optional<double> spacing_ratio;
  std::optional<int> endpoints;
  std::optional<double> shell;
  std::optional<double> rotation;
  std::optional<double> power;
  std::optional<Orientation> orientation;
  // Table 2, tree d: "at final level, build subgraphs around endpoints from all previous
  // levels", not only the last level's.
  bool every_endpoint = false;
};

// The iterated subgraphs of later levels: around each endpoint a cone-shaped graph (a portion
// of a sphere of half-angle a) oriented along v_g, from the previous root to the endpoint.
struct IterationParameters {
  int levels = 0;              // iterated levels after the first
  double radius = 0.8;         // metres: the first iterated level's subgraph radius
  double size_ratio = 0.5;     // each further level's radius relative to the one before
  double half_angle = 0.7;     // radians: a
  double spacing_ratio = 0.2;  // node spacing as a fraction of the subgraph radius
  int endpoints = 5;           // per subgraph (before the light's factor)
  double shell = 0.3;          // endpoint shell, as a fraction of the subgraph radius
  double rotation = 0.0;       // radians per level turning v_g downward (negative: up)
  bool use_lifespan = false;   // the paper's lifespan rule (bushes)
  double lifespan = 3.0;       // the first level's endpoints' lifespan
  double terminate_probability = 0.3;
  double power = 1.5;  // z of the iterated levels
  Vec3 light{0, 0, 1};
  double light_strength = 0.0;       // 0: the light plays no part; up to 1
  std::vector<LevelSettings> table;  // row k: iterated level k + 1 (the paper's level k + 2)
};

// One iterated level with every setting decided.
struct Level {
  double radius = 0.0;
  double half_angle = 0.0;
  double spacing_ratio = 0.0;
  int endpoints = 0;
  double shell = 0.0;
  double rotation = 0.0;
  double power = 0.0;
  Orientation orientation = Orientation::along;
  bool every_endpoint = false;
};

// Levels 1..it.levels: a row's settings where it has them, else `[iteration]`'s; a level
// without its own radius takes the previous level's times size_ratio.
std::vector<Level> resolve_levels(const IterationParameters& it);

}  // namespace landsim::trees::graph_paths
