#include "renderer/atmosphere/standard_atmosphere.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "renderer/detail/number_table.h"
#include "renderer/spectra/spectral_colour.h"

namespace landsim::renderer {

// The CSV files of data/atmosphere/, compiled in by renderer/CMakeLists.txt.
extern const std::string_view kUsStandardCsv;
extern const std::string_view kThuillierCsv;
extern const std::string_view kOzoneCrossSectionCsv;

namespace {

// The column whose optical depth Bodhaine et al.'s equation 30 gives: 1013.25 hPa of dry air
// with 360 ppm CO2 (mean molecular mass 28.9649 g/mol, their equation 17) under g at 45
// degrees latitude and sea level (9.80616 m/s^2): P N_A / (m_a g) molecules per m^2.
constexpr double kBodhaineColumn = 101325.0 * 6.0221367e23 / (28.9649e-3 * 9.80616);

StandardAtmosphere load_us_standard() {
  StandardAtmosphere a;
  std::vector<double> air, ozone;
  for (const auto& row : detail::number_rows(kUsStandardCsv, "afgl_1986_us_standard.csv")) {
    if (row.size() != 5) throw std::logic_error("embedded afgl_1986_us_standard.csv: 5 columns");
    a.heights.push_back(row[0]);
    a.pressures.push_back(row[1]);
    air.push_back(row[3]);
    ozone.push_back(row[4]);
  }
  a.air = DensityProfile(a.heights, air);
  a.ozone = DensityProfile(a.heights, ozone);
  return a;
}

struct Tabulated {
  std::vector<double> x, y;
  double linear(double at) const {  // clamped at the ends
    if (at <= x.front()) return y.front();
    if (at >= x.back()) return y.back();
    const auto i =
        static_cast<std::size_t>(std::upper_bound(x.begin(), x.end(), at) - x.begin() - 1);
    const double f = (at - x[i]) / (x[i + 1] - x[i]);
    return y[i] + f * (y[i + 1] - y[i]);
  }
};

Tabulated load_pairs(std::string_view csv, const char* name) {
  Tabulated t;
  for (const auto& row : detail::number_rows(csv, name)) {
    if (row.size() != 2) throw std::logic_error(std::string("embedded ") + name + ": 2 columns");
    t.x.push_back(row[0]);
    t.y.push_back(row[1]);
  }
  return t;
}

const Tabulated& thuillier() {
  static const Tabulated t = load_pairs(kThuillierCsv, "thuillier_2003.csv");
  return t;
}

const Tabulated& ozone_windows() {
  static const Tabulated t = load_pairs(kOzoneCrossSectionCsv, "ozone_cross_section_233k.csv");
  return t;
}

}  // namespace

const StandardAtmosphere& us_standard_atmosphere() {
  static const StandardAtmosphere a = load_us_standard();
  return a;
}

double rayleigh_cross_section(double nm) {
  // Bodhaine, Wood, Dutton and Slusser 1999, J. Atmos. Oceanic Technol. 16, equation 30,
  // lambda in micrometres.
  const double l = nm * 1e-3, l2 = l * l;
  const double tau = 0.0021520 * (1.0455996 - 341.29061 / l2 - 0.90230850 * l2) /
                     (1.0 + 0.0027059889 / l2 - 85.968563 * l2);
  return tau / kBodhaineColumn;
}

double ozone_cross_section(double nm) {
  const Tabulated& t = ozone_windows();
  if (nm < t.x.front() || nm >= t.x.back() + 10.0) return 0.0;
  const auto i = static_cast<std::size_t>((nm - t.x.front()) / 10.0);
  return t.y[std::min(i, t.y.size() - 1)];
}

Spectrum rayleigh_cross_sections(const SpectralGrid& grid) {
  return grid.average(rayleigh_cross_section);
}
Spectrum ozone_cross_sections(const SpectralGrid& grid) {
  return grid.average(ozone_cross_section);
}

Spectrum solar_irradiance_toa(double distance, const SpectralGrid& grid) {
  const double f = 1.0 / (distance * distance);
  return grid.average([&](double nm) { return thuillier().linear(nm) * f; });
}

double earth_sun_distance(int day_of_year) {
  const double days = 365.256;  // the anomalistic year
  return 1.0 - 0.01672 * std::cos(2.0 * std::numbers::pi * (day_of_year - 4) / days);
}

}  // namespace landsim::renderer
