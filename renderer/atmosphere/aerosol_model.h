#pragma once
// A named aerosol model tabulated by wavelength (docs/ATMOSPHERE.md "Aerosol models"): the
// extinction, single-scattering albedo and phase function a dataset gives at each of its
// wavelengths, as RAMI4ATM's continental and desert aerosols (Govaerts 2021) give them
// (data/atmosphere/, compiled in). Between its wavelengths every quantity is linear in
// wavelength (Eradiate's reading of the same files); beyond the first and last, the end's.
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "renderer/atmosphere/phase_function.h"

namespace landsim::renderer {

class AerosolModel {
 public:
  // "rami4atm-continental" or "rami4atm-desert", read once; std::invalid_argument for another
  // name (the scenario reader refuses it first, naming the key).
  static std::shared_ptr<const AerosolModel> named(const std::string& name);
  static const std::vector<std::string>& names();

  const std::string& name() const { return name_; }
  // The extinction at `nm` over that at 550 nm: the aerosol's optical depth at 550 nm times
  // this is its depth at `nm`.
  double relative_extinction(double nm) const;
  double single_scattering_albedo(double nm) const;
  // The phase function at `nm`: the two nearest wavelengths' tables mixed linearly, on the
  // dataset's scattering angles.
  PhaseFunction phase(double nm) const;
  // Its values there (sr^-1, the dataset's normalisation) at the dataset's scattering angles
  // (degrees, increasing): what a mean over wavelengths is taken of.
  std::vector<double> phase_values(double nm) const;
  const std::vector<double>& angles_deg() const { return angles_; }

 private:
  static std::shared_ptr<const AerosolModel> load(const std::string& name, const std::string& file,
                                                  std::string_view csv);
  struct Bracket {
    std::size_t i = 0;
    double f = 0.0;  // weight of i + 1
  };
  Bracket bracket(double nm) const;
  double linear(const std::vector<double>& y, double nm) const;

  std::string name_;
  std::vector<double> wavelengths_, extinction_, albedo_;
  std::vector<double> angles_;              // 0 to 180 degrees, from the dataset's cosines
  std::vector<std::vector<double>> phase_;  // per wavelength, per cosine, sr^-1
};

}  // namespace landsim::renderer
