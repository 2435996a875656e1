#pragma once
// Branch widths by the pipe model (Shinozaki 1964, as in Palubicki 2009): a tip internode
// has the tip width; elsewhere d^n = sum of d_i^n over the internodes above the node, plus
// the kept width of a shed branch there; a pruned stub keeps its width. A width constraint
// on an internode sets n for its subtree (outside nested constraints' subtrees): n is solved
// by Newton-Raphson so that the internode gets the constrained width.
#include <cstdint>
#include <vector>

#include "trees/self_organizing/parameters.h"
#include "trees/self_organizing/plant.h"

namespace landsim::trees::self_organizing {

struct ExponentSolution {
  std::uint32_t internode = 0;
  double exponent = 2.0;
  bool reached = true;  // false: clamped to [0.5, 20] without reaching the width
};

// Sets every living internode's width; returns the exponent solved per constraint.
std::vector<ExponentSolution> assign_widths(Plant& plant, const WidthParameters& widths);

// The exponent of every internode (the innermost constraint around it, else the default),
// as assign_widths used them.
std::vector<double> exponents(const Plant& plant, const WidthParameters& widths,
                              const std::vector<ExponentSolution>& solved);

}  // namespace landsim::trees::self_organizing
