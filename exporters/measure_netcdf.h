#pragma once
// A distant measure and its energy budgets as NetCDF-4 with the CF conventions (CF-1.8), for
// users who read radiative-transfer results with xarray or ncdump (docs/CANOPIES.md
// "Measures"): one dimension `direction` with the view's zenith and azimuth as coordinates,
// the BRF and radiance with their standard errors along it (and per band along `band`); the
// budgets' shares along `illumination` ("sun", "isotropic"), each with its standard error.
// Written under a temporary name and renamed when complete.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "renderer/measures/distant_measure.h"
#include "renderer/measures/energy_budget.h"

namespace landsim::exporters {

struct MeasureRecord {
  std::string scenario;
  double sun_zenith_deg = 0.0, sun_azimuth_deg = 0.0;
  std::uint64_t samples = 0;  // paths per direction
  std::vector<renderer::DistantResult> directions;
  // RAMI's signed view zenith of each direction, in the principal plane (else empty).
  std::vector<double> signed_view_zenith_deg;
  std::vector<std::string> band_names;
  // At the bottom of the atmosphere: the directions' values are HDRFs, and `bhr` the
  // bi-hemispherical reflectance there.
  bool bottom_of_atmosphere = false;
  std::optional<renderer::DistantResult> bhr;
  std::uint64_t budget_paths = 0;
  std::optional<renderer::EnergyBudget> budget_sun, budget_isotropic;
};

// Throws std::runtime_error naming the file and NetCDF's reason when it cannot be written.
void write_measure_netcdf(const std::filesystem::path& path, const MeasureRecord& record);

}  // namespace landsim::exporters
