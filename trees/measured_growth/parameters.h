#pragma once
// Measured-growth species (London plane from Modesto street-tree data): the age functions
// (allometry equations) and the parameters of the parametric L-system they drive.
#include <string>
#include <string_view>

#include "trees/measured_growth/allometry.h"

namespace landsim::params {
class TableReader;
}

namespace landsim::trees::measured_growth {

struct Parameters {
  Allometry allometry = modesto_london_plane();
  double age = 30.0;               // years since planting, when a scenario gives none
  double scaffold_interval = 1.0;  // years between scaffold limbs leaving the leader
  int max_generations = 6;         // bifurcations along a scaffold
  double min_scale = 0.15;         // branches with a smaller c_l do not bifurcate
  double l_max = 0.0;              // metres: a c_l = 1 branch's maximum length; 0 = H_max
  double c_dbh = 1.0;              // trunk diameter at 1.37 m = c_dbh * f_DBH
  double divergence = 2.2689;      // radians (130 degrees) between successive scaffolds
  double angle_noise = 0.087;      // radians: random part of the bifurcation angle
  double leaf_area = 0.025;        // m2 per leaf
  double leaf_threshold = 0.03;    // metres: leaves on branches thinner than this
  // Each tree's deviation from the equations, in units of the database's scatter (its
  // Sigma): 1 as measured, 0 every tree the equations' mean.
  double scatter = 1.0;
};

// H_max: the largest height, f_H at the data's end.
double max_height(const Parameters& p);
// l_max: a c_l = 1 branch's maximum length, the species' or else H_max.
double length_scale(const Parameters& p);

// Section 5, as landsim reads it (docs/MEASURED_GROWTH.md): a branch grows the tree's height
// curve replayed from its creation, l(t) = c_l f_H(t - t0) (the paper's l_max / H_max is the
// trunk's ratio, 1), and bifurcates when it reaches its maximum length c_l l_max (a child's
// maximum is its parent's times the same s as its c_l): when f_H(t - t0) = l_max, the same
// time after creation for every branch. Infinite if f_H never gets there (l_max = H_max: the
// literal reading, in which nothing forks before the data's end).
double bifurcation_age(const Parameters& p);

// A branch's length at time t (before the crown's shape ends it): c_l f_H(t - t0).
double grown_length(const Parameters& p, double c_l, double t, double t0);

// Reads the core's tables ([allometry.*], [growth], [leaves]); InputError names file, line,
// key and what was expected.
Parameters read_parameters(params::TableReader& root, const std::string& source);

}  // namespace landsim::trees::measured_growth
