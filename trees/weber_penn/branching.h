#pragma once
// The paper's branching rules as small functions: how many children a stem gets, which way
// each turns (nRotate) and how far it tilts (nDownAngle), and error diffusion, which turns
// fractional counts per segment into whole ones without losing the total.
#include "trees/weber_penn/parameters.h"
#include "trees/weber_penn/random.h"

namespace landsim::trees::weber_penn {

// Rounds a stream of fractional amounts so the running total never drifts by more than
// half: each call returns round(value + carried error) and carries the remainder.
class ErrorDiffusion {
 public:
  int next(double value) {
    const int n = static_cast<int>(value + error_ + 0.5);
    error_ -= n - value;
    return n;
  }
  double error() const { return error_; }

 private:
  double error_ = 0.0;
};

// Children a stem of `level` gets (before error diffusion), section 4.3:
//  trunk:   nBranches of level 1;
//  level 1: nBranches x (0.2 + 0.8 (length / parent_length) / parent_length_child_max);
//  deeper:  nBranches x (1 - 0.5 offset / parent_length).
double child_count(int level, int branches, double length, double parent_length,
                   double parent_length_child_max, double offset);

// nRotate >= 0: each child turns a further nRotate (+- nRotateV) about the parent;
// negative: children alternate sides at 180 + nRotate (+- nRotateV). `state` carries the
// running angle (or the side) from one child to the next.
double next_rotation(double& state, const LevelParameters& child, Random& r);

// nDownAngle +- nDownAngleV; a negative nDownAngleV instead sweeps the angle along the
// parent by position `ratio` (1 at the lowest child, 0 at the tip), as the paper prints it:
// nDownAngle + V (1 - 2 ShapeRatio(0, ratio)).
double down_angle(const LevelParameters& child, double ratio, Random& r);

}  // namespace landsim::trees::weber_penn
