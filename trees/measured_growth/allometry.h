#pragma once
// Urban Tree Database allometry (McPherson, van Doorn and Peper 2016): the global functions
// of age that drive the London plane growth model. DBH from age; height, crown diameter,
// crown height and leaf area from DBH. Each equation is clamped to the range of its
// predicted value (the database's "Apps min/max"), and ages to the range where DBH grows.
#include <string>

namespace landsim::trees::measured_growth {

enum class ModelForm { lin, quad, cub, loglogw1 };

struct Equation {
  ModelForm form = ModelForm::lin;
  double a = 0, b = 0, c = 0, d = 0;
  double min = 0, max = 1e9;  // range of the predicted value

  // The predicted value at x, clamped to [min, max].
  double operator()(double x) const;
};

// Parses the database's model name: "lin", "quad", "cub", "loglogw1".
bool parse_form(const std::string& name, ModelForm& form);

struct Allometry {
  Equation dbh;     // centimetres, from age (years)
  Equation height;  // metres, from DBH
  Equation crown_diameter;
  Equation crown_height;  // metres: from the crown base to the top
  Equation leaf_area;     // square metres, from DBH
  double max_age = 65;    // ages above are clamped (DBH stops growing there)

  double f_dbh(double age) const { return dbh(age); }
  double f_height(double age) const { return height(dbh(age)); }
  double f_crown_diameter(double age) const { return crown_diameter(dbh(age)); }
  double f_crown_height(double age) const { return crown_height(dbh(age)); }
  double f_leaf_area(double age) const { return leaf_area(dbh(age)); }
};

// The first age at which DBH reaches its maximum (where the database's range ends), found by
// bisection on the increasing part of the DBH equation; `limit` if it never does.
double age_of_max_dbh(const Equation& dbh, double limit = 200.0);

// The Modesto (InlVal) London plane equations, as the species file gives them.
Allometry modesto_london_plane();

}  // namespace landsim::trees::measured_growth
