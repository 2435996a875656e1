#pragma once
// The dimensions the Urban Tree Database measures, taken from a tree's geometry: height (the
// highest point), crown diameter (twice the farthest point of branches and leaves from the
// trunk axis), crown height (from the lowest branch or leaf to the top), DBH (the trunk's
// diameter at 1.37 m) and leaf area (one side of every leaf polygon).
#include "trees/geometry.h"

namespace landsim::trees::measured_growth {

struct Dimensions {
  double height_m = 0.0;
  double crown_diameter_m = 0.0;
  double crown_height_m = 0.0;
  double dbh_cm = 0.0;
  double leaf_area_m2 = 0.0;
};

Dimensions measure(const TreeGeometry& tree);

}  // namespace landsim::trees::measured_growth
