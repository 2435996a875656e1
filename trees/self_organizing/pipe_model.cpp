#include "trees/self_organizing/pipe_model.h"

#include <algorithm>
#include <cmath>

namespace landsim::trees::self_organizing {
namespace {

constexpr double kLowest = 0.5, kHighest = 20.0;

// Width and its derivative with respect to the exponent.
struct Width {
  double d = 0.0;
  double slope = 0.0;
};

// The pipe-model width of every internode of `members` (ascending indices) for exponent n;
// internodes in `fixed` (nested constraints) keep their current width.
void widths_for(const Plant& plant, const std::vector<std::uint32_t>& members,
                const std::vector<bool>& fixed, double n, double tip, std::vector<Width>& scratch) {
  for (std::size_t k = members.size(); k-- > 0;) {
    const std::uint32_t i = members[k];
    const Internode& node = plant[i];
    Width& w = scratch[i];
    if (fixed[i]) {
      w = {node.width, 0.0};
      continue;
    }
    if (node.stub) {
      w = {node.frozen_width, 0.0};
      continue;
    }
    double sum = 0.0, dsum = 0.0;  // S = sum d_i^n and dS/dn
    bool any = false;
    const auto add = [&](double d, double slope) {
      const double p = std::pow(d, n);
      sum += p;
      dsum += p * (std::log(d) + n * slope / d);
      any = true;
    };
    for (std::uint32_t child : {node.main, node.lateral})
      if (child != kNone && plant[child].alive) add(scratch[child].d, scratch[child].slope);
    if (node.shed_lateral_width > 0.0) add(node.shed_lateral_width, 0.0);
    if (!any) {
      w = {tip, 0.0};
      continue;
    }
    const double d = std::pow(sum, 1.0 / n);
    w = {d, d * (dsum / (sum * n) - std::log(sum) / (n * n))};
  }
}

// Newton-Raphson on d_root(n) = target, kept inside a shrinking bracket (d falls as n
// rises), with bisection when a Newton step leaves it.
ExponentSolution solve(const Plant& plant, const std::vector<std::uint32_t>& members,
                       const std::vector<bool>& fixed, std::uint32_t root, double target,
                       double start, double tip, std::vector<Width>& scratch) {
  double lo = kLowest, hi = kHighest, n = std::clamp(start, lo, hi);
  for (int iteration = 0; iteration < 100; ++iteration) {
    widths_for(plant, members, fixed, n, tip, scratch);
    const double error = scratch[root].d - target;
    if (std::abs(error) <= 1e-10 * target) return {root, n, true};
    if (error > 0)
      lo = n;
    else
      hi = n;  // too wide: a larger exponent narrows it
    double next = scratch[root].slope != 0.0 ? n - error / scratch[root].slope : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (hi - lo < 1e-12) break;
    n = next;
  }
  widths_for(plant, members, fixed, n, tip, scratch);
  return {root, n, std::abs(scratch[root].d - target) <= 1e-6 * target};
}

}  // namespace

std::vector<double> exponents(const Plant& plant, const WidthParameters& widths,
                              const std::vector<ExponentSolution>& solved) {
  std::vector<double> n(plant.size(), widths.exponent);
  std::vector<double> at(plant.size(), 0.0);  // constraint exponent at its root, else 0
  for (const ExponentSolution& s : solved) at[s.internode] = s.exponent;
  for (std::uint32_t i = 0; i < plant.size(); ++i) {
    const std::uint32_t p = plant[i].parent;
    n[i] = at[i] > 0.0 ? at[i] : (p == kNone ? widths.exponent : n[p]);
  }
  return n;
}

std::vector<ExponentSolution> assign_widths(Plant& plant, const WidthParameters& widths) {
  // Deepest constraints first: a child's index is above its parent's.
  std::vector<WidthConstraint> constraints;
  for (const WidthConstraint& c : widths.constraints)
    if (c.internode < plant.size() && plant[c.internode].alive) constraints.push_back(c);
  std::sort(
      constraints.begin(), constraints.end(),
      [](const WidthConstraint& a, const WidthConstraint& b) { return a.internode > b.internode; });
  std::vector<Width> scratch(plant.size());
  std::vector<bool> fixed(plant.size(), false);
  std::vector<ExponentSolution> solved;
  for (const WidthConstraint& c : constraints) {
    const std::vector<std::uint32_t> members = plant.subtree(c.internode);
    const ExponentSolution s =
        solve(plant, members, fixed, c.internode, c.width, widths.exponent, widths.tip, scratch);
    for (std::uint32_t i : members)
      if (!fixed[i]) plant[i].width = scratch[i].d, fixed[i] = true;
    solved.push_back(s);
  }
  // The rest with the default exponent, nested constraints' widths fixed.
  std::vector<std::uint32_t> rest;
  for (std::uint32_t i = 0; i < plant.size(); ++i)
    if (plant[i].alive) rest.push_back(i);
  widths_for(plant, rest, fixed, widths.exponent, widths.tip, scratch);
  for (std::uint32_t i : rest)
    if (!fixed[i]) plant[i].width = scratch[i].d;
  return solved;
}

}  // namespace landsim::trees::self_organizing
