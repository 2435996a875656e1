#include "brf_command.h"

#include <fmt/format.h>
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <iostream>
#include <limits>
#include <numbers>
#include <optional>
#include <sstream>
#include <utility>

#include "core/atomic_file.h"
#include "core/input_error.h"
#include "exporters/measure_netcdf.h"
#include "renderer/measures/distant_measure.h"
#include "renderer/measures/energy_budget.h"
#include "renderer/measures/measure_directions.h"
#include "renderer/spectra/sensor_band.h"
#include "scenario_input.h"
#include "scenes/builder/scene_builder.h"

namespace landsim::app {
namespace {

// "a,b": two numbers and a comma, nothing else; empty otherwise.
std::optional<std::pair<double, double>> number_pair(const std::string& text) {
  double a = 0.0, b = 0.0;
  char comma = 0, rest = 0;
  std::istringstream in(text);
  if (!(in >> a >> comma >> b) || comma != ',' || (in >> rest)) return std::nullopt;
  return std::pair{a, b};
}

// "zenith,azimuth" in degrees, each in range; InputError naming the option.
renderer::DistantDirection parse_direction(const std::string& text) {
  const auto pair = number_pair(text);
  const auto [zenith, azimuth] = pair.value_or(std::pair{-1.0, -1.0});
  if (!(zenith >= 0.0 && zenith < 90.0) || !(azimuth >= 0.0 && azimuth <= 360.0))
    throw InputError("--direction " + text +
                     ": expected zenith,azimuth in degrees (zenith 0 to below 90, azimuth 0-360)");
  return {zenith, azimuth};
}

// RAMI's signed view zenith in the principal plane: negative on the sun's side.
double signed_zenith(const renderer::DistantDirection& d, double sun_azimuth) {
  const double delta = std::fmod(std::abs(d.azimuth_deg - sun_azimuth), 360.0);
  return std::abs(delta) < 1e-9 || std::abs(delta - 360.0) < 1e-9 ? -d.zenith_deg : d.zenith_deg;
}

nlohmann::json value_json(const renderer::DistantValue& v) {
  return {{"mean", v.mean}, {"se", v.standard_error}};
}

nlohmann::json budget_json(const renderer::EnergyBudget& b, int paths) {
  return {{"paths", paths},
          {"albedo", value_json(b.reflected)},
          {"absorbed_leaves", value_json(b.absorbed_leaves)},
          {"absorbed_stems", value_json(b.absorbed_stems)},
          {"absorbed_soil", value_json(b.absorbed_soil)},
          {"absorbed_other", value_json(b.absorbed_other)},
          {"absorbed_haze", value_json(b.absorbed_haze)},
          {"soil_direct", value_json(b.soil_direct)},
          {"soil_diffuse", value_json(b.soil_diffuse)},
          {"total", value_json(b.total)}};
}

// A reflectance factor's key: the BRF above the atmosphere, the HDRF at its bottom.
std::string factor_key(bool bottom) { return bottom ? "hdrf" : "brf"; }

nlohmann::json result_json(const scenes::Scenario& s, const std::vector<std::string>& band_names,
                           const std::vector<renderer::DistantResult>& results, int spp, bool plane,
                           bool bottom) {
  const std::string key = factor_key(bottom);
  nlohmann::json directions = nlohmann::json::array();
  for (const renderer::DistantResult& r : results) {
    nlohmann::json bands = nlohmann::json::object();
    for (std::size_t b = 0; b < r.band_brf.size(); ++b)
      bands[band_names[b]] = {{key, r.band_brf[b].mean},
                              {key + "_se", r.band_brf[b].standard_error}};
    nlohmann::json d = {{"zenith_deg", r.direction.zenith_deg},
                        {"azimuth_deg", r.direction.azimuth_deg},
                        {"relative_azimuth_deg", renderer::rami_relative_azimuth(
                                                     r.direction.azimuth_deg, s.sun.azimuth_deg)},
                        {key, r.brf.mean},
                        {key + "_se", r.brf.standard_error},
                        {"radiance", r.radiance.mean},
                        {"radiance_se", r.radiance.standard_error},
                        {"paths", r.paths},
                        {"bands", bands}};
    if (plane) d["view_zenith_deg"] = signed_zenith(r.direction, s.sun.azimuth_deg);
    directions.push_back(std::move(d));
  }
  return {{"scenario", s.source},
          {"level", bottom ? "boa" : "toa"},
          {"sun_zenith_deg", 90.0 - s.sun.elevation_deg},
          {"sun_azimuth_deg", s.sun.azimuth_deg},
          {"samples", spp},
          {"directions", directions}};
}

// A number of the JSON, or NaN where it holds null (a monochromatic run's luminance).
double number(const nlohmann::json& v) {
  return v.is_number() ? v.get<double>() : std::numeric_limits<double>::quiet_NaN();
}

// One row per direction: the luminance's factor and radiance, then each band's factor.
std::string result_csv(const nlohmann::json& j, const std::vector<std::string>& band_names) {
  const std::string key = factor_key(j["level"] == "boa");
  std::string out =
      fmt::format("view_zenith_deg,zenith_deg,azimuth_deg,{0},{0}_se,radiance,radiance_se", key);
  for (const std::string& b : band_names) out += fmt::format(",{0}_{1},{0}_{1}_se", key, b);
  out += ",relative_azimuth_deg,paths\n";
  for (const auto& d : j["directions"]) {
    out += fmt::format(
        "{},{},{},{},{},{},{}", d.value("view_zenith_deg", d["zenith_deg"].get<double>()),
        d["zenith_deg"].get<double>(), d["azimuth_deg"].get<double>(), number(d[key]),
        number(d[key + "_se"]), number(d["radiance"]), number(d["radiance_se"]));
    for (const std::string& b : band_names)
      out += fmt::format(",{},{}", d["bands"][b][key].get<double>(),
                         d["bands"][b][key + "_se"].get<double>());
    out += fmt::format(",{},{}\n", d["relative_azimuth_deg"].get<double>(),
                       d["paths"].get<std::uint64_t>());
  }
  return out;
}

// The bi-hemispherical reflectance at the bottom of the atmosphere, luminance and bands.
nlohmann::json bhr_json(const renderer::DistantResult& r,
                        const std::vector<std::string>& band_names) {
  nlohmann::json bands = nlohmann::json::object();
  for (std::size_t b = 0; b < r.band_brf.size(); ++b)
    bands[band_names[b]] = {{"mean", r.band_brf[b].mean}, {"se", r.band_brf[b].standard_error}};
  return {{"mean", r.brf.mean}, {"se", r.brf.standard_error}, {"paths", r.paths}, {"bands", bands}};
}

// A monochromatic run's table: a row per direction, a column per wavelength.
void print_monochromatic(const nlohmann::json& j, const std::vector<std::string>& names,
                         const std::string& key) {
  std::string head = fmt::format("{:>7} {:>7}", "zenith", "azimuth");
  for (const std::string& n : names) head += fmt::format("  {:>17}", n);
  std::cout << head << "\n";
  if (j.contains("bhr")) {
    std::string row = fmt::format("{:>15}", "BHR");
    for (const std::string& n : names)
      row += fmt::format("  {:.4f} +- {:.4f}", j["bhr"]["bands"][n]["mean"].get<double>(),
                         j["bhr"]["bands"][n]["se"].get<double>());
    std::cout << row << "\n";
  }
  for (const auto& d : j["directions"]) {
    std::string row =
        fmt::format("{:>7.1f} {:>7.1f}", d.value("view_zenith_deg", d["zenith_deg"].get<double>()),
                    d["azimuth_deg"].get<double>());
    for (const std::string& n : names)
      row += fmt::format("  {:.4f} +- {:.4f}", d["bands"][n][key].get<double>(),
                         d["bands"][n][key + "_se"].get<double>());
    std::cout << row << "\n";
  }
}

// The measures of one scene: each direction's, and the BHR at the bottom of the atmosphere.
struct Measured {
  std::vector<renderer::DistantResult> directions;
  std::optional<renderer::DistantResult> bhr;
};

Measured measure(const renderer::Scene& scene,
                 const std::vector<renderer::DistantDirection>& directions,
                 const renderer::DistantMeasureOptions& options) {
  Measured m{renderer::measure_distant(scene, directions, options), std::nullopt};
  if (options.bottom_of_atmosphere) m.bhr = renderer::measure_bhr(scene, options);
  return m;
}

// Each wavelength's own factor appended as a band; the luminance, which a single wavelength
// has none of, NaN.
void append_wavelength(renderer::DistantResult& into, const renderer::DistantResult& run) {
  constexpr double kNone = std::numeric_limits<double>::quiet_NaN();
  into.brf = {kNone, kNone};
  into.radiance = {kNone, kNone};
  into.band_brf.push_back(run.band_brf.at(0));
  into.paths += run.paths;
}

// Monochromatic runs (docs/CANOPIES.md "Measures"): the scene measured once per wavelength,
// the medium and the sun evaluated at it, its one band that wavelength's bin.
Measured measure_monochromatic(renderer::Scene scene, const std::vector<double>& wavelengths,
                               const std::vector<renderer::DistantDirection>& directions,
                               const renderer::DistantMeasureOptions& options) {
  Measured all;
  all.directions.resize(directions.size());
  for (std::size_t i = 0; i < directions.size(); ++i) all.directions[i].direction = directions[i];
  if (options.bottom_of_atmosphere) all.bhr.emplace();
  for (const double nm : wavelengths) {
    scene.spectral_grid.monochromatic_nm = nm;
    scene.bands = {renderer::monochromatic_band(nm)};
    const Measured one = measure(scene, directions, options);
    for (std::size_t i = 0; i < directions.size(); ++i)
      append_wavelength(all.directions[i], one.directions[i]);
    if (all.bhr) append_wavelength(*all.bhr, *one.bhr);
  }
  return all;
}

// The wavelengths of --wavelength: within landsim's bins, each once.
void check_wavelengths(const BrfArgs& args) {
  for (std::size_t i = 0; i < args.wavelengths.size(); ++i) {
    const double nm = args.wavelengths[i];
    if (!(nm >= renderer::kFirstWavelength && nm <= renderer::kLastWavelength))
      throw InputError(fmt::format("--wavelength {}: expected {} to {} nm (landsim's bins)", nm,
                                   renderer::kFirstWavelength, renderer::kLastWavelength));
    for (std::size_t j = 0; j < i; ++j)
      if (args.wavelengths[j] == nm)
        throw InputError(fmt::format("--wavelength {}: given twice", nm));
  }
  if (!args.wavelengths.empty() && args.budget_paths_given && args.budget_paths > 0)
    throw InputError(
        "--budget-paths: the energy budget is of the luminance, which a monochromatic run "
        "(--wavelength) has none of: measure it in a run without --wavelength");
}

// The directions asked for: --direction's or --hemisphere's (in the frame named), else RAMI's
// principal plane.
std::vector<renderer::DistantDirection> directions_of(const BrfArgs& args,
                                                      const scenes::Scenario& s) {
  const bool rami = args.azimuth_frame == "rami";
  if (!args.hemisphere.empty()) {
    if (!args.directions.empty())
      throw InputError("--hemisphere " + args.hemisphere +
                       ": give either --hemisphere or --direction, not both");
    const auto steps = number_pair(args.hemisphere);
    if (!steps)
      throw InputError("--hemisphere " + args.hemisphere +
                       ": expected ZSTEP,ASTEP in degrees (e.g. 10,30)");
    return renderer::hemisphere_grid(steps->first, steps->second, s.sun.azimuth_deg, rami);
  }
  std::vector<renderer::DistantDirection> out;
  for (const std::string& d : args.directions) {
    renderer::DistantDirection direction = parse_direction(d);
    if (rami)
      direction.azimuth_deg = renderer::compass_azimuth(direction.azimuth_deg, s.sun.azimuth_deg);
    out.push_back(direction);
  }
  if (out.empty()) out = renderer::principal_plane(s.sun.azimuth_deg);
  return out;
}

// The relative standard error to trace to: --target-se's; none with --spp alone (exactly those
// paths); else the default precision.
double target_of(const BrfArgs& args) {
  if (args.target_se_given) return args.target_se;
  return args.spp_given ? 0.0 : kDefaultTargetSe;
}

}  // namespace

CLI::App* add_brf_command(CLI::App& app, BrfArgs& args) {
  CLI::App* cmd = app.add_subcommand(
      "brf", "Measure a periodic cell as radiative-transfer codes do: its BRF seen from far away");
  cmd->add_option("scenario", args.scenario, "Scenario TOML file with [terrain] periodic = true")
      ->required();
  cmd->add_option("--spp", args.spp,
                  "Paths per direction: exactly these, or with --target-se to start with")
      ->check(CLI::Range(2, 1 << 26))
      ->each([&args](const std::string&) { args.spp_given = true; });
  cmd->add_option("--target-se", args.target_se,
                  "Trace each direction until the BRF's standard error is at most this fraction "
                  "of it (of 0.01 for a BRF below it), up to 2^26 paths; 0: --spp paths exactly "
                  "(default 0.005, or 0 when --spp is given alone)")
      ->check(CLI::Range(0.0, 0.5))
      ->each([&args](const std::string&) { args.target_se_given = true; });
  cmd->add_option("--direction", args.directions,
                  "zenith,azimuth (degrees) towards the sensor; repeatable (default: RAMI's "
                  "principal plane, view zenith -75 to 75 every 2)");
  cmd->add_option("--hemisphere", args.hemisphere,
                  "ZSTEP,ASTEP: the zenith/azimuth grid DART and LESS write (zenith 0, then every "
                  "ZSTEP below 90, each at every ASTEP of azimuth), instead of the plane");
  cmd->add_option("--azimuth-frame", args.azimuth_frame,
                  "compass: azimuths clockwise from north (default); rami: from the sun's azimuth, "
                  "counter-clockwise seen from above (--direction and --hemisphere read in it)")
      ->check(CLI::IsMember({"compass", "rami"}))
      ->capture_default_str();
  cmd->add_option("--out", args.out, "Directory for brf.json, brf.csv and brf.nc (NetCDF-4, CF)");
  cmd->add_option("--budget-paths", args.budget_paths,
                  "Paths from the sun for the energy budget (albedo, absorption; 0: none)")
      ->check(CLI::Range(0, 1 << 28))
      ->each([&args](const std::string&) { args.budget_paths_given = true; });
  cmd->add_option("--threads", args.threads, "Worker threads (0: every core)")
      ->check(CLI::Range(0, 1024));
  cmd->add_option("--level", args.level,
                  "toa: the BRF seen from above the atmosphere (default); boa: the HDRF and BHR "
                  "just above the cell, under the atmosphere's light")
      ->check(CLI::IsMember({"toa", "boa"}));
  cmd->add_option("--wavelength", args.wavelengths,
                  "Monochromatic runs at these wavelengths, nm (comma-separated or repeated): "
                  "the medium and the sun evaluated at each, one factor per wavelength")
      ->delimiter(',');
  cmd->add_flag("--json", args.json, "Print the measure as one JSON object on stdout");
  add_set_option(*cmd, args.sets);
  return cmd;
}

int run_brf(const BrfArgs& args) {
  check_wavelengths(args);
  scenes::Scenario scenario = scenario_or_default(args.scenario, args.sets);
  if (!scenario.terrain.periodic)
    throw InputError(scenario.source +
                     ": landsim brf measures a periodic cell: set [terrain] periodic = true");
  // Every tree and cloud at full detail: a measure has no camera to range them from.
  scenario.render.degradation = false;
  renderer::Scene scene = scenes::build_scene(scenario);
  const std::vector<renderer::DistantDirection> directions = directions_of(args, scenario);
  const bool plane = args.directions.empty() && args.hemisphere.empty();
  renderer::DistantMeasureOptions options;
  options.samples = static_cast<std::uint64_t>(args.spp);
  options.seed = scenario.render.sampling_seed.value_or(scenario.render.seed);
  options.threads = args.threads;
  options.target_relative_error = target_of(args);
  const bool bottom = args.level == "boa";
  options.bottom_of_atmosphere = bottom;
  const bool monochromatic = !args.wavelengths.empty();
  if (monochromatic) options.target_band = 0;  // --target-se bounds each wavelength's factor
  // A monochromatic run takes the scene over (its grid and band are set per wavelength): a
  // canopy's scene is not copied; nothing below reads it then but the budget, which it skips.
  Measured measured =
      monochromatic ? measure_monochromatic(std::move(scene), args.wavelengths, directions, options)
                    : measure(scene, directions, options);
  exporters::MeasureRecord record;
  record.scenario = scenario.source;
  record.sun_zenith_deg = 90.0 - scenario.sun.elevation_deg;
  record.sun_azimuth_deg = scenario.sun.azimuth_deg;
  record.samples = options.samples;
  record.directions = std::move(measured.directions);
  for (const renderer::DistantResult& r : record.directions)
    if (plane)
      record.signed_view_zenith_deg.push_back(signed_zenith(r.direction, scenario.sun.azimuth_deg));
  if (monochromatic)
    for (const double nm : args.wavelengths)
      record.band_names.push_back(renderer::monochromatic_band(nm).name);
  else
    for (const renderer::SpectralBand& b : scene.bands) record.band_names.push_back(b.name);
  record.bottom_of_atmosphere = bottom;
  nlohmann::json j =
      result_json(scenario, record.band_names, record.directions, args.spp, plane, bottom);
  j["target_se"] = options.target_relative_error;
  if (monochromatic) j["wavelengths_nm"] = args.wavelengths;
  if (bottom) {
    record.bhr = measured.bhr;
    j["bhr"] = bhr_json(*record.bhr, record.band_names);
  }
  if (args.budget_paths > 0 && !monochromatic) {
    renderer::EnergyOptions budget;
    budget.samples = static_cast<std::uint64_t>(args.budget_paths);
    budget.seed = options.seed;
    budget.threads = args.threads;
    record.budget_paths = budget.samples;
    // A dark sun (a sky alone lights the cell) has no budget of its own.
    const Vec3f& sun = scene.sun.irradiance;
    if (sun.x > 0.0f || sun.y > 0.0f || sun.z > 0.0f) {
      record.budget_sun = renderer::measure_energy(scene, budget);
      j["budget"] = budget_json(*record.budget_sun, args.budget_paths);
    }
    // Under an isotropic sky: the bi-hemispherical reflectance, and what the canopy absorbs of
    // diffuse light.
    budget.illumination = renderer::Illumination::isotropic;
    record.budget_isotropic = renderer::measure_energy(scene, budget);
    j["budget_isotropic"] = budget_json(*record.budget_isotropic, args.budget_paths);
  }
  if (!args.out.empty()) {
    std::filesystem::create_directories(args.out);
    write_file_atomically(std::filesystem::path(args.out) / "brf.json", j.dump(2) + "\n");
    write_file_atomically(std::filesystem::path(args.out) / "brf.csv",
                          result_csv(j, record.band_names));
    exporters::write_measure_netcdf(std::filesystem::path(args.out) / "brf.nc", record);
  }
  if (args.json) {
    std::cout << j.dump() << "\n";
    return 0;
  }
  if (j.contains("budget_isotropic")) {
    std::cout << fmt::format("{:<16} {:>17} {:>17}\n", "", "sun", "isotropic sky");
    const auto share = [&](const char* budget, const char* k) {
      if (!j.contains(budget)) return fmt::format("{:>17}", "-");
      return fmt::format("{:.4f} +- {:.4f}", j[budget][k]["mean"].get<double>(),
                         j[budget][k]["se"].get<double>());
    };
    for (const char* k : {"albedo", "absorbed_leaves", "absorbed_stems", "absorbed_soil",
                          "absorbed_haze", "soil_direct", "soil_diffuse", "total"})
      std::cout << fmt::format("{:<16} {}  {}\n", k, share("budget", k),
                               share("budget_isotropic", k));
  }
  const std::string key = factor_key(bottom);
  if (monochromatic) {
    print_monochromatic(j, record.band_names, key);
    return 0;
  }
  if (bottom)
    std::cout << fmt::format("BHR {:.4f} +- {:.4f}\n", j["bhr"]["mean"].get<double>(),
                             j["bhr"]["se"].get<double>());
  for (const auto& d : j["directions"])
    std::cout << fmt::format("{:>7.1f} {:>7.1f}  {} {:.4f} +- {:.4f}  radiance {:.6g}\n",
                             d.value("view_zenith_deg", d["zenith_deg"].get<double>()),
                             d["azimuth_deg"].get<double>(), bottom ? "HDRF" : "BRF",
                             d.value(key, std::nan("")), d.value(key + "_se", std::nan("")),
                             d["radiance"].get<double>());
  return 0;
}

}  // namespace landsim::app
