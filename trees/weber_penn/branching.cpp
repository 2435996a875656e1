#include "trees/weber_penn/branching.h"

#include <cmath>

#include "trees/weber_penn/shape_ratio.h"

namespace landsim::trees::weber_penn {

double child_count(int level, int branches, double length, double parent_length,
                   double parent_length_child_max, double offset) {
  if (level == 0) return branches;
  if (level == 1) {
    const double rel =
        parent_length_child_max > 0.0 ? length / parent_length / parent_length_child_max : 0.0;
    return branches * (0.2 + 0.8 * rel);
  }
  return branches * (1.0 - 0.5 * offset / parent_length);
}

double next_rotation(double& state, const LevelParameters& child, Random& r) {
  if (child.rotate >= 0.0) {
    state = std::fmod(state + child.rotate + r.var(child.rotate_v) + 360.0, 360.0);
    return state;
  }
  if (std::abs(state) != 1.0) state = 1.0;
  state = -state;
  return state * (180.0 + child.rotate + r.var(child.rotate_v));
}

double down_angle(const LevelParameters& child, double ratio, Random& r) {
  if (child.down_angle_v >= 0.0) return child.down_angle + r.var(child.down_angle_v);
  // As printed (section 4.3), through the conical ShapeRatio: the sweep runs from nDownAngle -
  // V at the lowest child to nDownAngle + 0.6 V at the tip (the appendix species were tuned so).
  return child.down_angle + child.down_angle_v * (1.0 - 2.0 * shape_ratio(0, ratio));
}

}  // namespace landsim::trees::weber_penn
