#include "trees/measured_growth/parameters.h"

#include <toml++/toml.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "core/input_error.h"
#include "params/table_reader.h"

namespace landsim::trees::measured_growth {
namespace {

using params::TableReader;

constexpr params::Range kCoefficient{-1e6, 1e6};

Equation read_equation(TableReader r) {
  Equation e;
  const std::string form = r.choice("form", {"lin", "quad", "cub", "loglogw1"});
  parse_form(form, e.form);
  e.a = r.number("a", kCoefficient, e.a);
  e.b = r.number("b", kCoefficient, e.b);
  e.c = r.number("c", kCoefficient, e.c);
  e.d = r.number("d", kCoefficient, e.d);
  e.min = r.number("min", kCoefficient, e.min);
  e.max = r.number("max", kCoefficient, e.max);
  if (!(e.min < e.max)) r.fail("max", "expected a range with min < max");
  e.sigma = r.number("sigma", {0, 1e6}, e.sigma);
  if (!parse_weight(r.choice("weight", {"1", "1/x", "1/x^2", "1/sqrt(x)"}, "1"), e.weight))
    r.fail("weight", "expected \"1\", \"1/x\", \"1/x^2\" or \"1/sqrt(x)\"");
  r.finish();
  return e;
}

void read_allometry(TableReader r, Allometry& a) {
  // Each equation the database fitted; an absent one keeps its default.
  for (auto [key, e] :
       {std::pair{"dbh", &a.dbh}, std::pair{"height", &a.height},
        std::pair{"crown_diameter", &a.crown_diameter}, std::pair{"crown_height", &a.crown_height},
        std::pair{"leaf_area", &a.leaf_area}})
    if (r.has(key))
      *e = read_equation(r.table(key));
    else
      r.value(key, "an equation table (form, a, b, c, d, min, max)");
  r.finish();
  a.max_age = age_of_max_dbh(a.dbh);
}

void read_growth(TableReader r, Parameters& p) {
  p.age = r.number("age", {0, 500}, p.age);
  p.scaffold_interval = r.number("scaffold_interval", {0.25, 20}, p.scaffold_interval);
  p.max_generations = static_cast<int>(r.integer("max_generations", 0, 12, p.max_generations));
  p.min_scale = r.number("min_scale", {0, 1}, p.min_scale);
  p.l_max = r.number("l_max", {0, 100}, p.l_max);
  p.c_dbh = r.number("c_dbh", {0.1, 10}, p.c_dbh);
  p.divergence = r.angle("divergence", {0, 360}, p.divergence);
  p.angle_noise = r.angle("angle_noise", {0, 45}, p.angle_noise);
  p.scatter = r.number("scatter", {0, 3}, p.scatter);
  r.finish();
}

void read_leaves(TableReader r, Parameters& p) {
  p.leaf_area = r.number("area", {1e-4, 1}, p.leaf_area);
  p.leaf_threshold = r.number("threshold", {1e-3, 1}, p.leaf_threshold);
  r.finish();
}

}  // namespace

double max_height(const Parameters& p) { return p.allometry.f_height(p.allometry.max_age); }

double length_scale(const Parameters& p) { return p.l_max > 0.0 ? p.l_max : max_height(p); }

double bifurcation_age(const Parameters& p) {
  const Allometry& a = p.allometry;
  const double wanted = length_scale(p);
  if (wanted <= a.f_height(0.0)) return 0.0;
  if (wanted > a.f_height(a.max_age)) return std::numeric_limits<double>::infinity();
  double lo = 0.0, hi = a.max_age;  // f_H increases with age
  for (int k = 0; k < 60; ++k) {
    const double mid = 0.5 * (lo + hi);
    (a.f_height(mid) < wanted ? lo : hi) = mid;
  }
  return hi;
}

double grown_length(const Parameters& p, double c_l, double t, double t0) {
  return c_l * p.allometry.f_height(t - t0);
}

Parameters read_parameters(params::TableReader& root, const std::string& source) {
  Parameters p;
  read_allometry(root.table("allometry"), p.allometry);
  read_growth(root.table("growth"), p);
  read_leaves(root.table("leaves"), p);
  // Explosion guards: leaves at the largest leaf area, and scaffolds times their branches.
  const double leaves = p.allometry.leaf_area(p.allometry.dbh.max) / p.leaf_area;
  if (leaves > 2e6)
    throw InputError(source + ": leaves.area " + std::to_string(p.leaf_area) +
                     " would make about " + std::to_string(static_cast<long long>(leaves)) +
                     " leaves at full leaf area (limit 2,000,000): raise leaves.area");
  // A branch born at its maximum length would fork at once, every fork again: refused.
  if (!(bifurcation_age(p) > 0.0))
    throw InputError(
        source + ": growth.l_max " + params::format_number(p.l_max) +
        " m is no longer than a branch is at its creation (" +
        params::format_number(p.allometry.f_height(0.0)) +
        " m for c_l = 1, the height of the planted tree): every branch would fork at once; "
        "raise it");
  const double scaffolds = p.allometry.max_age / p.scaffold_interval;
  const double per_scaffold = std::pow(2.0, p.max_generations + 1);
  if (scaffolds * per_scaffold > 2e6)
    throw InputError(source +
                     ": growth.scaffold_interval and growth.max_generations would make "
                     "about " +
                     std::to_string(static_cast<long long>(scaffolds * per_scaffold)) +
                     " branches (limit 2,000,000)");
  return p;
}

}  // namespace landsim::trees::measured_growth
