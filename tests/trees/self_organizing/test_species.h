#pragma once
// A small crown grown in an ellipsoidal envelope, shared by the self-organising tests.
#include "trees/self_organizing/parameters.h"

namespace landsim::trees::self_organizing::testing {

inline Parameters ellipsoid_crown(int steps) {
  Parameters p;
  p.steps = steps;
  p.internode_length = 0.2;
  p.envelope.kind = EnvelopeKind::ellipsoid;
  p.envelope.centre = {0, 0, 2};
  p.envelope.radii = {1.5, 1.5, 2};
  p.envelope.density = 60;
  return p;
}

}  // namespace landsim::trees::self_organizing::testing
