#pragma once
// Urban Tree Database allometry (McPherson, van Doorn and Peper 2016): the global functions
// of age that drive the London plane growth model. DBH from age; height, crown diameter,
// crown height and leaf area from DBH. Each equation is clamped to the range of its
// predicted value (the database's "Apps min/max"), and ages to the range where DBH grows.
#include <algorithm>
#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace landsim::trees::measured_growth {

enum class ModelForm { lin, quad, cub, loglogw1 };
// The database's model weight: residuals of a weighted fit have variance sigma / weight(x).
enum class Weight { one, inverse_x, inverse_x2, inverse_sqrt_x };

struct Equation {
  ModelForm form = ModelForm::lin;
  double a = 0, b = 0, c = 0, d = 0;
  double min = 0, max = 1e9;  // range of the predicted value
  // The database's Sigma and model weight (docs/MEASURED_GROWTH.md "Scatter"): for the
  // polynomial forms the weighted residuals' mean square, for loglogw1 the root mean square
  // of ln(y); 0: no scatter known.
  double sigma = 0.0;
  Weight weight = Weight::one;

  // The predicted value at x, clamped to [min, max].
  double operator()(double x) const;
  // The same, not clamped.
  double unclamped(double x) const;
  // One tree's curve (set by `deviated`; empty and 1: the mean): samples of its running
  // maximum every kCurveStep from 0 (polynomial forms), or its factor (loglogw1).
  std::vector<double> own_curve;
  double own_factor = 1.0;
  static constexpr double kCurveStep = 0.25;  // years or centimetres

  // This tree's value at x, clamped to [min, max].
  double own(double x) const;
  // The curve of a tree z standard deviations of the database's scatter from the mean.
  // loglogw1: the mean times exp(z sigma - sigma^2 / 2) (its mean carries the
  // exp(sigma^2 / 2)); polynomial forms: the running maximum of y(s) + z sqrt(sigma /
  // weight(s)), so that a tree never shrinks where the scatter still widens and the mean has
  // stopped growing (sampled to x = 200, interpolated between samples).
  Equation deviated(double z) const;
};

// Parses the database's model name: "lin", "quad", "cub", "loglogw1".
bool parse_form(const std::string& name, ModelForm& form);
// Parses its model weight: "1", "1/x", "1/x^2", "1/sqrt(x)".
bool parse_weight(const std::string& name, Weight& weight);

struct Allometry {
  Equation dbh;     // centimetres, from age (years)
  Equation height;  // metres, from DBH
  Equation crown_diameter;
  Equation crown_height;  // metres: from the crown base to the top
  Equation leaf_area;     // square metres, from DBH
  double max_age = 65;    // ages above are clamped (DBH stops growing there)
  // The tree's own curves (Equation::deviated; the mean tree's unless `individual` drew
  // them). The other dimensions follow the tree's own DBH.
  double f_dbh(double age) const { return dbh.own(age); }
  double f_height(double age) const { return height.own(f_dbh(age)); }
  double f_crown_diameter(double age) const { return crown_diameter.own(f_dbh(age)); }
  // The crown keeps the mean crown ratio at the tree's DBH: the database publishes no
  // correlation between the equations' residuals, and a crown height drawn apart from the
  // height put crown bases below the lowest scaffolds (docs/MEASURED_GROWTH.md "Scatter").
  double f_crown_height(double age) const {
    const double d = f_dbh(age), h = height.own(d);
    return std::min(crown_height(d) * h / height(d), h);
  }
  double f_leaf_area(double age) const { return leaf_area.own(f_dbh(age)); }
};

// The tree of `seed`: `a` with deviations drawn from a standard normal distribution
// truncated at +-2.5, times `scatter` (0: the equations' mean tree).
Allometry individual(const Allometry& a, std::uint64_t seed, double scatter);

// The first age at which DBH reaches its maximum (where the database's range ends), found by
// bisection on the increasing part of the DBH equation; `limit` if it never does.
double age_of_max_dbh(const Equation& dbh, double limit = 200.0);

// The Modesto (InlVal) London plane equations, as the species file gives them.
Allometry modesto_london_plane();

}  // namespace landsim::trees::measured_growth
