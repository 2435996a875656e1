#pragma once
// The graph-paths tests' tree: a sphere crown of `crown_radius` centred 3 m up, over a trunk
// cylinder 0.2 m wide and 2 m tall; 0.15 m node spacing.
#include "trees/graph_paths/generator.h"

namespace landsim::trees::graph_paths::testing {

inline Parameters crown_on_trunk(double crown_radius = 1.5, int endpoints = 120) {
  VolumePrimitive crown;
  crown.origin = {0, 0, 3};
  crown.radius = crown_radius;
  VolumePrimitive trunk;
  trunk.kind = PrimitiveKind::cylinder;
  trunk.radius = 0.2;
  trunk.height = 2.0;
  Parameters p;
  p.volume = InitialVolume({crown, trunk});
  p.spacing = 0.15;
  p.endpoints = endpoints;
  p.shell = 0.3;
  return p;
}

}  // namespace landsim::trees::graph_paths::testing
