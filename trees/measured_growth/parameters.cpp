#include "trees/measured_growth/parameters.h"

#include <toml++/toml.h>

#include <cmath>
#include <numbers>

#include "core/input_error.h"
#include "trees/toml_reader.h"

namespace landsim::trees::measured_growth {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

Equation read_equation(const TomlReader& r, const toml::node& n, const std::string& key) {
  const toml::table& t = r.table(n, key);
  Equation e;
  bool has_form = false;
  r.read_table(t, key, "form, a, b, c, d, min, max",
               [&](const std::string& k, const std::string& sub, const toml::node& v) {
                 if (k == "form") {
                   const auto name = v.value<std::string>();
                   if (!name || !parse_form(*name, e.form))
                     r.refuse(v, sub,
                              "\"lin\", \"quad\", \"cub\" or \"loglogw1\" (the database's model "
                              "forms)");
                   has_form = true;
                 } else if (k == "a")
                   e.a = r.number(v, sub, -1e6, 1e6);
                 else if (k == "b")
                   e.b = r.number(v, sub, -1e6, 1e6);
                 else if (k == "c")
                   e.c = r.number(v, sub, -1e6, 1e6);
                 else if (k == "d")
                   e.d = r.number(v, sub, -1e6, 1e6);
                 else if (k == "min")
                   e.min = r.number(v, sub, -1e6, 1e6);
                 else if (k == "max")
                   e.max = r.number(v, sub, -1e6, 1e6);
                 else
                   return false;
                 return true;
               });
  if (!has_form) r.refuse(t, key + ".form", "the model form");
  if (!(e.min < e.max)) r.refuse(t, key + ".max", "a range with min < max");
  return e;
}

void read_allometry(const TomlReader& r, const toml::table& t, Allometry& a) {
  r.read_table(t, "allometry", "dbh, height, crown_diameter, crown_height, leaf_area",
               [&](const std::string& k, const std::string& key, const toml::node& v) {
                 Equation* e = k == "dbh"              ? &a.dbh
                               : k == "height"         ? &a.height
                               : k == "crown_diameter" ? &a.crown_diameter
                               : k == "crown_height"   ? &a.crown_height
                               : k == "leaf_area"      ? &a.leaf_area
                                                       : nullptr;
                 if (e != nullptr) *e = read_equation(r, v, key);
                 return e != nullptr;
               });
  a.max_age = age_of_max_dbh(a.dbh);
}

void read_growth(const TomlReader& r, const toml::table& t, Parameters& p) {
  r.read_table(t, "growth",
               "age, scaffold_interval, bifurcation_period, max_generations, min_scale, l_max, "
               "c_dbh, divergence, angle_noise",
               [&](const std::string& k, const std::string& key, const toml::node& v) {
                 if (k == "age")
                   p.age = r.number(v, key, 0, 500);
                 else if (k == "scaffold_interval")
                   p.scaffold_interval = r.number(v, key, 0.25, 20);
                 else if (k == "bifurcation_period")
                   p.bifurcation_period = r.number(v, key, 0.5, 50);
                 else if (k == "max_generations")
                   p.max_generations = r.integer(v, key, 0, 12);
                 else if (k == "min_scale")
                   p.min_scale = r.number(v, key, 0, 1);
                 else if (k == "l_max")
                   p.l_max = r.number(v, key, 0, 100);
                 else if (k == "c_dbh")
                   p.c_dbh = r.number(v, key, 0.1, 10);
                 else if (k == "divergence")
                   p.divergence = r.number(v, key, 0, 360) * kDegree;
                 else if (k == "angle_noise")
                   p.angle_noise = r.number(v, key, 0, 45) * kDegree;
                 else
                   return false;
                 return true;
               });
}

void read_leaves(const TomlReader& r, const toml::table& t, Parameters& p) {
  r.read_table(t, "leaves", "area, threshold",
               [&](const std::string& k, const std::string& key, const toml::node& v) {
                 if (k == "area")
                   p.leaf_area = r.number(v, key, 1e-4, 1);
                 else if (k == "threshold")
                   p.leaf_threshold = r.number(v, key, 1e-3, 1);
                 else
                   return false;
                 return true;
               });
}

}  // namespace

Parameters parse_parameters(std::string_view toml_text, const std::string& source) {
  const toml::table root = toml::parse(toml_text, source);  // species.cpp parsed it already
  const TomlReader r(source);
  Parameters p;
  for (auto&& [k, v] : root) {
    if (k == "core" || k == "name" || k == "colours") continue;  // species.cpp's keys
    const std::string key(k.str());
    if (k == "allometry")
      read_allometry(r, r.table(v, key), p.allometry);
    else if (k == "growth")
      read_growth(r, r.table(v, key), p);
    else if (k == "leaves")
      read_leaves(r, r.table(v, key), p);
    else
      r.refuse(v, key, "one of core, name, colours, [allometry], [growth], [leaves]");
  }
  // Explosion guards: leaves at the largest leaf area, and scaffolds times their branches.
  const double leaves = p.allometry.leaf_area(p.allometry.dbh.max) / p.leaf_area;
  if (leaves > 2e6)
    throw InputError(source + ": leaves.area " + std::to_string(p.leaf_area) +
                     " would make about " + std::to_string(static_cast<long long>(leaves)) +
                     " leaves at full leaf area (limit 2,000,000): raise leaves.area");
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
