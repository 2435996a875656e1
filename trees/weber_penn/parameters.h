#pragma once
// Every parameter of Weber & Penn's appendix (plus the extensions Arbaro's species files use:
// Smooth, LeafQuality, LeafStemLen, LeafDistrib, LeafBend, nBranchDist), with defaults,
// ranges and the explosion guard. Angles are in degrees, lengths in metres.
#include <array>
#include <string>

#include "trees/leaf_shape.h"
#include "trees/param_table.h"

namespace landsim::params {
class TableReader;
}

namespace landsim::trees::weber_penn {

// Per recursion level n (0 = trunk). Stems deeper than 3 use level 3's values.
struct LevelParameters {
  double down_angle = 30.0, down_angle_v = 0.0;   // nDownAngle, nDownAngleV
  double rotate = 120.0, rotate_v = 0.0;          // nRotate, nRotateV
  int branches = 10;                              // nBranches (0Branches: trunks)
  double branch_dist = 1.0;                       // nBranchDist (Arbaro)
  double length = 0.5, length_v = 0.0;            // nLength, nLengthV
  double taper = 1.0;                             // nTaper, 0..3
  double seg_splits = 0.0;                        // nSegSplits
  double split_angle = 0.0, split_angle_v = 0.0;  // nSplitAngle, nSplitAngleV
  int curve_res = 3;                              // nCurveRes
  double curve = 0.0, curve_back = 0.0, curve_v = 0.0;
};

struct Parameters {
  int shape = 0;
  double base_size = 0.25;
  double scale = 10.0, scale_v = 0.0;
  double z_scale = 1.0, z_scale_v = 0.0;
  int levels = 3;
  double ratio = 0.02, ratio_power = 1.0;
  int lobes = 0;
  double lobe_depth = 0.0;
  double flare = 0.5;
  double trunk_scale = 1.0, trunk_scale_v = 0.0;  // 0Scale, 0ScaleV
  int base_splits = 0;                            // 0BaseSplits
  int leaves = 0;                                 // negative: fan at the stem end
  LeafShape leaf_shape;
  double leaf_scale = 0.2, leaf_scale_x = 1.0;
  double leaf_quality = 1.0, leaf_stem_len = 0.5, leaf_bend = 0.3;
  int leaf_distrib = 4;
  double attraction_up = 0.0;
  double prune_ratio = 0.0, prune_width = 0.5, prune_width_peak = 0.5;
  double prune_power_low = 0.5, prune_power_high = 0.5;
  double smooth = 0.5;
  std::array<LevelParameters, 4> level;

  Parameters();
  const LevelParameters& at(int stem_level) const {
    return level[static_cast<std::size_t>(stem_level < 3 ? stem_level : 3)];
  }
};

// Limits that keep generation bounded (a few hundred MB at most).
inline constexpr double kMaxStems = 1e6;
inline constexpr double kMaxLeaves = 5e6;

// Reads every entry of `table` (unknown names, wrong types and out-of-range values throw
// InputError naming the parameter, its location and the limit), then refuses parameter
// sets whose expected stem or leaf count exceeds the limits. `file` names the source.
Parameters parse_parameters(const ParamTable& table, const std::string& file);
// The same from a TOML species file's top level, through the one parameter reader (unknown
// keys are refused by the caller's finish()).
Parameters read_parameters(params::TableReader& root, const std::string& file);

// Expected stems and leaves of a tree (used by the explosion guard; also printed in docs).
struct SizeEstimate {
  double stems = 0.0;
  double leaves = 0.0;
  std::string dominant;  // the parameter that multiplies the count most
};
SizeEstimate estimate_size(const Parameters& p);

// Every parameter name this core accepts (for documentation and tests).
std::vector<std::string> parameter_names();

}  // namespace landsim::trees::weber_penn
