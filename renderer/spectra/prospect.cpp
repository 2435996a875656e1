#include "renderer/spectra/prospect.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string_view>

#include "renderer/detail/number_table.h"
#include "renderer/spectra/spectral_colour.h"

namespace landsim::renderer {

// data/spectra/prospect_d_dataSpec_PDB.txt, compiled in by renderer/CMakeLists.txt.
extern const std::string_view kProspectDataTxt;

namespace {

// Columns of the data file: wavelength, refractive index, then the specific absorption
// coefficients of chlorophyll a+b, carotenoids, anthocyanins, brown pigments, water, dry matter.
struct ProspectData {
  std::vector<double> wavelength, index, cab, car, ant, brown, water, dry;
};

const ProspectData& data() {
  static const ProspectData d = [] {
    ProspectData out;
    for (const auto& row : detail::number_rows(kProspectDataTxt, "prospect_d_dataSpec_PDB.txt")) {
      if (row.size() != 8)
        throw std::logic_error("embedded prospect_d_dataSpec_PDB.txt: expected 8 columns");
      out.wavelength.push_back(row[0]);
      out.index.push_back(row[1]);
      out.cab.push_back(row[2]);
      out.car.push_back(row[3]);
      out.ant.push_back(row[4]);
      out.brown.push_back(row[5]);
      out.water.push_back(row[6]);
      out.dry.push_back(row[7]);
    }
    return out;
  }();
  return d;
}

// Allen et al. (1973)'s transmissivity of a dielectric plane surface of refractive index n,
// averaged over the solid angle of incidence from 0 to alpha degrees (Stern 1964's closed
// form, as PROSPECT uses it).
double average_transmissivity(double alpha_deg, double n) {
  const double n2 = n * n, np = n2 + 1.0, nm = n2 - 1.0;
  const double a = (n + 1.0) * (n + 1.0) / 2.0;
  const double k = -(n2 - 1.0) * (n2 - 1.0) / 4.0;
  const double sa = std::sin(alpha_deg * std::numbers::pi / 180.0);
  const double b2 = sa * sa - np / 2.0;
  const double b1 = alpha_deg == 90.0 ? 0.0 : std::sqrt(b2 * b2 + k);
  const double b = b1 - b2;
  const double ts =
      (k * k / (6.0 * b * b * b) + k / b - b / 2.0) - (k * k / (6.0 * a * a * a) + k / a - a / 2.0);
  const double tp1 = -2.0 * n2 * (b - a) / (np * np);
  const double tp2 = -2.0 * n2 * np * std::log(b / a) / (nm * nm);
  const double tp3 = n2 * (1.0 / b - 1.0 / a) / 2.0;
  const double tp4 = 16.0 * n2 * n2 * (n2 * n2 + 1.0) *
                     std::log((2.0 * np * b - nm * nm) / (2.0 * np * a - nm * nm)) /
                     (np * np * np * nm * nm);
  const double tp5 = 16.0 * n2 * n2 * n2 *
                     (1.0 / (2.0 * np * b - nm * nm) - 1.0 / (2.0 * np * a - nm * nm)) /
                     (np * np * np);
  return (ts + tp1 + tp2 + tp3 + tp4 + tp5) / (2.0 * sa * sa);
}

// Transmission of one elementary layer of absorption k (Beer's law over all directions of a
// diffuse flux): (1 - k) e^-k + k^2 E1(k).
double layer_transmission(double k) {
  if (k <= 0.0) return 1.0;
  const double e1 = -std::expint(-k);  // E1(k) = -Ei(-k)
  return (1.0 - k) * std::exp(-k) + k * k * e1;
}

struct Plate {
  double reflectance, transmittance;
};

// One wavelength of the plate model: the rough top plate, N - 1 more by Stokes' equations.
Plate leaf_at(double n, double k, double plates) {
  const double tau = layer_transmission(k);
  const double t_alpha = average_transmissivity(40.0, n), r_alpha = 1.0 - t_alpha;
  const double t12 = average_transmissivity(90.0, n), r12 = 1.0 - t12;
  const double t21 = t12 / (n * n), r21 = 1.0 - t21;
  // The top plate, lit at up to 40 degrees, and an inner plate, lit diffusely.
  const double denominator = 1.0 - r21 * r21 * tau * tau;
  const double top_t = t_alpha * tau * t21 / denominator;
  const double top_r = r_alpha + r21 * tau * top_t;
  const double t = t12 * tau * t21 / denominator;
  const double r = r12 + r21 * tau * t;
  // Stokes: the N - 1 remaining plates as one.
  double sub_r = 0.0, sub_t = 1.0;
  if (r + t >= 1.0) {  // no absorption
    sub_t = t / (t + (1.0 - t) * (plates - 1.0));
    sub_r = 1.0 - sub_t;
  } else {
    const double d = std::sqrt((1.0 + r + t) * (1.0 + r - t) * (1.0 - r + t) * (1.0 - r - t));
    const double a = (1.0 + r * r - t * t + d) / (2.0 * r);
    const double b = (1.0 - r * r + t * t + d) / (2.0 * t);
    const double b_n1 = std::pow(b, plates - 1.0);
    const double b_n2 = b_n1 * b_n1;
    const double denom = a * a * b_n2 - 1.0;
    sub_r = a * (b_n2 - 1.0) / denom;
    sub_t = b_n1 * (a * a - 1.0) / denom;
  }
  const double joined = 1.0 - sub_r * r;
  return {top_r + top_t * sub_r * t / joined, top_t * sub_t / joined};
}

}  // namespace

LeafSpectra prospect_d(const LeafContents& leaf, double last_nm) {
  const ProspectData& d = data();
  LeafSpectra out;
  const double n = leaf.structure;
  for (std::size_t i = 0; i < d.wavelength.size() && d.wavelength[i] <= last_nm; ++i) {
    out.wavelength.push_back(d.wavelength[i]);
    const double k =
        (leaf.chlorophyll * d.cab[i] + leaf.carotenoids * d.car[i] + leaf.anthocyanins * d.ant[i] +
         leaf.brown * d.brown[i] + leaf.water * d.water[i] + leaf.dry_matter * d.dry[i]) /
        n;
    const Plate p = leaf_at(d.index[i], k, n);
    out.reflectance.push_back(p.reflectance);
    out.transmittance.push_back(p.transmittance);
  }
  return out;
}

LeafOptics leaf_optics(const LeafContents& leaf) {
  const LeafSpectra s = prospect_d(leaf, kLastWavelength);
  const double first = s.wavelength.front();
  const auto at = [&](const std::vector<double>& v, double nm) {
    const auto i = static_cast<std::size_t>(std::clamp(nm - first, 0.0, double(v.size() - 1)));
    return v[i];
  };
  // Bin averages over the data's 1 nm samples (integer wavelengths inside each bin).
  const auto average = [&](const std::vector<double>& v) {
    return bin_average([&](double nm) { return at(v, std::floor(nm)); });
  };
  return {average(s.reflectance), average(s.transmittance)};
}

}  // namespace landsim::renderer
