#pragma once
// `landsim brf SCENARIO [--json] [--spp N] [--out DIR] [--direction Z,A ...]`: what a
// radiative-transfer code measures of a periodic cell (docs/CANOPIES.md "Measures"): the BRF
// seen from infinitely far in RAMI's principal plane (or the directions given), with its
// standard errors; where the sun's light goes (albedo, absorbed by leaves, stems and soil,
// transmitted to the soil); brf.json and brf.csv in DIR.
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace landsim::app {

// The precision a measure is taken to when none is asked for: 0.5% of each BRF (RAMI's
// reference codes' agreement is about 1%).
inline constexpr double kDefaultTargetSe = 0.005;

struct BrfArgs {
  std::vector<std::string> sets;
  std::string scenario;
  std::string out;                      // empty: nothing written
  std::vector<std::string> directions;  // "zenith,azimuth" in degrees; empty: principal plane
  int spp = 4096;                       // paths per direction (with a target: to start with)
  // Relative standard error each direction is traced to (0: --spp paths exactly). By default
  // kDefaultTargetSe, unless --spp alone is given (then exactly those paths).
  double target_se = 0.0;
  bool spp_given = false, target_se_given = false;
  // "compass": azimuths clockwise from north; "rami": from the sun's, counter-clockwise.
  std::string azimuth_frame = "compass";
  std::string hemisphere;     // "ZSTEP,ASTEP": the zenith/azimuth grid; empty: none
  int budget_paths = 100000;  // paths from the sun for the energy budget; 0: none
  int threads = 0;
  bool json = false;
  // "toa": the BRF above the atmosphere (or the cell); "boa": the HDRF and BHR just above the
  // cell, under the atmosphere's light.
  std::string level = "toa";
  // Monochromatic runs (docs/CANOPIES.md "Measures"): one measure per wavelength, nm, the
  // medium and the sun evaluated there; empty: the scenario's bins and bands.
  std::vector<double> wavelengths;
  bool budget_paths_given = false;  // --budget-paths on the command line
};

CLI::App* add_brf_command(CLI::App& app, BrfArgs& args);
int run_brf(const BrfArgs& args);

}  // namespace landsim::app
