#include "trees/measured_growth/allometry.h"

#include <algorithm>
#include <cmath>

namespace landsim::trees::measured_growth {

double Equation::operator()(double x) const {
  double y = 0.0;
  switch (form) {
    case ModelForm::lin:
      y = a + b * x;
      break;
    case ModelForm::quad:
      y = a + x * (b + c * x);
      break;
    case ModelForm::cub:
      y = a + x * (b + x * (c + d * x));
      break;
    case ModelForm::loglogw1:
      // As the database prints it: c (the MSE) halved inside the outer logarithm.
      y = std::exp(a + b * std::log(std::log(std::max(x, 0.0) + 1.0) + c / 2.0));
      break;
  }
  return std::clamp(y, min, max);
}

bool parse_form(const std::string& name, ModelForm& form) {
  if (name == "lin") return form = ModelForm::lin, true;
  if (name == "quad") return form = ModelForm::quad, true;
  if (name == "cub") return form = ModelForm::cub, true;
  if (name == "loglogw1") return form = ModelForm::loglogw1, true;
  return false;
}

double age_of_max_dbh(const Equation& dbh, double limit) {
  if (dbh(limit) < dbh.max) return limit;
  double lo = 0.0, hi = limit;
  for (int k = 0; k < 60; ++k) {
    const double mid = 0.5 * (lo + hi);
    (dbh(mid) < dbh.max ? lo : hi) = mid;
  }
  return hi;
}

Allometry modesto_london_plane() {
  Allometry a;
  a.dbh = {ModelForm::cub, 2.74346, 2.76313, -0.04948, 0.0003, 2.74, 55.57};
  a.height = {ModelForm::quad, 0.90077, 0.47286, -0.00307, 0, 2.17, 17.7};
  a.crown_diameter = {ModelForm::quad, 0.41317, 0.36991, -0.00179, 0, 1.41, 15.44};
  a.crown_height = {ModelForm::loglogw1, -0.32476, 2.07239, 0.05105, 0, 1.34, 13.19};
  a.leaf_area = {ModelForm::loglogw1, -0.08181, 4.31097, 0.1981, 0, 4.17, 418.67};
  a.max_age = age_of_max_dbh(a.dbh);
  return a;
}

}  // namespace landsim::trees::measured_growth
