#include "renderer/atmosphere/aerosol_model.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string_view>

#include "renderer/detail/number_table.h"

namespace landsim::renderer {

// The CSV files of data/atmosphere/, compiled in by renderer/CMakeLists.txt.
extern const std::string_view kAerosolContinentalCsv;
extern const std::string_view kAerosolDesertCsv;

namespace {

constexpr double kReferenceWavelength = 550.0;  // nm: where an optical depth is stated

}  // namespace

const std::vector<std::string>& AerosolModel::names() {
  static const std::vector<std::string> n{"rami4atm-continental", "rami4atm-desert"};
  return n;
}

std::shared_ptr<const AerosolModel> AerosolModel::named(const std::string& name) {
  // Each read once: a medium is built for every measure and render.
  static const auto continental =
      load("rami4atm-continental", "aerosol_continental.csv", kAerosolContinentalCsv);
  static const auto desert = load("rami4atm-desert", "aerosol_desert.csv", kAerosolDesertCsv);
  if (name == names()[0]) return continental;
  if (name == names()[1]) return desert;
  throw std::invalid_argument("no aerosol model named " + name);
}

std::shared_ptr<const AerosolModel> AerosolModel::load(const std::string& name,
                                                       const std::string& file,
                                                       std::string_view csv) {
  auto m = std::make_shared<AerosolModel>();
  m->name_ = name;
  for (const auto& row : detail::number_rows(csv, file.c_str())) {
    if (row.size() != 5) throw std::logic_error("embedded " + file + ": 5 columns");
    if (m->wavelengths_.empty() || row[0] != m->wavelengths_.back()) {
      m->wavelengths_.push_back(row[0]);
      m->extinction_.push_back(row[1]);
      m->albedo_.push_back(row[2]);
      m->phase_.emplace_back();
    }
    // The table wants increasing angles: the dataset's cosines run from 1 down to -1.
    if (m->wavelengths_.size() == 1)
      m->angles_.push_back(std::acos(std::clamp(row[3], -1.0, 1.0)) * 180.0 / std::numbers::pi);
    m->phase_.back().push_back(row[4]);
  }
  for (const auto& p : m->phase_)
    if (p.size() != m->angles_.size())
      throw std::logic_error("embedded " + file + ": the same cosines at every wavelength");
  return m;
}

AerosolModel::Bracket AerosolModel::bracket(double nm) const {
  if (nm <= wavelengths_.front()) return {0, 0.0};
  if (nm >= wavelengths_.back()) return {wavelengths_.size() - 2, 1.0};
  const auto i = static_cast<std::size_t>(
      std::upper_bound(wavelengths_.begin(), wavelengths_.end(), nm) - wavelengths_.begin() - 1);
  return {i, (nm - wavelengths_[i]) / (wavelengths_[i + 1] - wavelengths_[i])};
}

double AerosolModel::linear(const std::vector<double>& y, double nm) const {
  const Bracket b = bracket(nm);
  return (1.0 - b.f) * y[b.i] + b.f * y[b.i + 1];
}

double AerosolModel::relative_extinction(double nm) const {
  return linear(extinction_, nm) / linear(extinction_, kReferenceWavelength);
}

double AerosolModel::single_scattering_albedo(double nm) const { return linear(albedo_, nm); }

std::vector<double> AerosolModel::phase_values(double nm) const {
  const Bracket b = bracket(nm);
  std::vector<double> values(angles_.size());
  for (std::size_t j = 0; j < angles_.size(); ++j)
    values[j] = (1.0 - b.f) * phase_[b.i][j] + b.f * phase_[b.i + 1][j];
  return values;
}

PhaseFunction AerosolModel::phase(double nm) const {
  return PhaseFunction::table(angles_, phase_values(nm));
}

}  // namespace landsim::renderer
