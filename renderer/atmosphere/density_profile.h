#pragma once
// A density tabulated by height (a standard atmosphere's air or ozone), exponential between
// its nodes: n(z) = n_i exp(-(z - z_i) / H_i) on [z_i, z_i+1], H_i from the two nodes' values,
// and the first and last pieces continued below and above the table. Piecewise exponential
// rather than linear because the air thins exponentially: with 1 km nodes the column above a
// height is then exact to the table's own rounding, and every quantity a ray needs has a closed
// form (docs/ATMOSPHERE.md "One atmosphere").
//
// The column above z, C(z), is what a plane-parallel atmosphere reduces every ray to: a ray
// from height a to height b in direction d crosses |C(a) - C(b)| / |d.z| of it.
#include <vector>

namespace landsim::renderer {

class DensityProfile {
 public:
  DensityProfile() = default;
  // Heights increasing (metres), densities positive, at least two nodes.
  DensityProfile(std::vector<double> heights, std::vector<double> densities);

  bool empty() const { return heights_.empty(); }
  double density(double z) const;
  // The integral of the density from z to infinity.
  double column_above(double z) const;
  // The height at which column_above equals `column` (finite for any column > 0).
  double height_of_column(double column) const;
  // The integral along a ray from height z leaving at vertical rate dz (its direction's z) for
  // a length t (t may be infinite).
  double along(double z, double dz, double t) const;
  // The length along that ray at which `along` reaches `depth`; `t` when it never does
  // within t.
  double length_at(double z, double dz, double t, double depth) const;
  // Every density scaled by f.
  void scale(double f);
  double top() const { return heights_.back(); }

 private:
  int piece(double z) const;  // -1 below the first node, n-1 above the last
  std::vector<double> heights_, densities_;
  double step_ = 0.0;  // the nodes' spacing when even (a standard profile's 1 km), else 0
  std::vector<double> scale_heights_;  // of the piece above each node (the last: continued)
  std::vector<double> column_;         // column above each node
};

}  // namespace landsim::renderer
