#include "exporters/measure_netcdf.h"

#include <netcdf.h>

#include <array>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "core/atomic_file.h"
#include "renderer/measures/measure_directions.h"

namespace landsim::exporters {
namespace {

// One NetCDF file being defined and written; every call checked, the file closed on the way
// out whatever happens.
class NetcdfFile {
 public:
  explicit NetcdfFile(std::filesystem::path path) : path_(std::move(path)) {
    check(nc_create(path_.c_str(), NC_NETCDF4 | NC_CLOBBER, &id_));
  }
  NetcdfFile(const NetcdfFile&) = delete;
  NetcdfFile& operator=(const NetcdfFile&) = delete;
  ~NetcdfFile() {
    if (id_ >= 0) nc_close(id_);
  }

  int dimension(const char* name, std::size_t length) {
    int d = 0;
    check(nc_def_dim(id_, name, length, &d));
    return d;
  }
  int variable(const char* name, nc_type type, std::vector<int> dims) {
    int v = 0;
    check(nc_def_var(id_, name, type, static_cast<int>(dims.size()), dims.data(), &v));
    return v;
  }
  void text(int var, const char* name, const std::string& value) {
    check(nc_put_att_text(id_, var, name, value.size(), value.c_str()));
  }
  void number(int var, const char* name, double value) {
    check(nc_put_att_double(id_, var, name, NC_DOUBLE, 1, &value));
  }
  void put(int var, const std::vector<double>& values) {
    check(nc_put_var_double(id_, var, values.data()));
  }
  void put(int var, const std::vector<std::string>& values) {
    std::vector<const char*> c;
    for (const std::string& s : values) c.push_back(s.c_str());
    check(nc_put_var_string(id_, var, c.data()));
  }
  void end_definitions() { check(nc_enddef(id_)); }
  void close() {
    const int id = std::exchange(id_, -1);
    check(nc_close(id));
  }

 private:
  void check(int status) const {
    if (status != NC_NOERR)
      throw std::runtime_error(path_.string() + ": NetCDF: " + nc_strerror(status));
  }
  std::filesystem::path path_;
  int id_ = -1;
};

// A measured quantity and its standard error, as CF ancillary variables.
struct Quantity {
  Quantity(std::string n, std::string l, std::string u, std::string s)
      : name(std::move(n)),
        long_name(std::move(l)),
        units(std::move(u)),
        standard_name(std::move(s)) {}
  std::string name, long_name, units, standard_name;
  std::vector<double> mean, error;
};

void define(NetcdfFile& f, const Quantity& q, const std::vector<int>& dims,
            const std::string& coordinates, std::vector<std::pair<int, const Quantity*>>& out) {
  const int v = f.variable(q.name.c_str(), NC_DOUBLE, dims);
  const int e = f.variable((q.name + "_standard_error").c_str(), NC_DOUBLE, dims);
  f.text(v, "long_name", q.long_name);
  f.text(e, "long_name", "Monte Carlo standard error of " + q.long_name);
  for (const int var : {v, e}) {
    f.text(var, "units", q.units);
    if (!coordinates.empty()) f.text(var, "coordinates", coordinates);
  }
  if (!q.standard_name.empty()) {
    f.text(v, "standard_name", q.standard_name);
    f.text(e, "standard_name", q.standard_name + " standard_error");
  }
  f.text(v, "ancillary_variables", q.name + "_standard_error");
  out.push_back({v, &q});
  out.push_back({e, nullptr});
}

std::vector<Quantity> direction_quantities(const MeasureRecord& r) {
  Quantity brf = r.bottom_of_atmosphere
                     ? Quantity{"hdrf",
                                "hemispherical-directional reflectance factor of the luminance at "
                                "the bottom of the atmosphere",
                                "1", ""}
                     : Quantity{"brf", "bidirectional reflectance factor of the luminance", "1",
                                "surface_bidirectional_reflectance"};
  Quantity radiance{"radiance", "luminance leaving the cell towards the sensor", "cd m-2", ""};
  for (const renderer::DistantResult& d : r.directions) {
    brf.mean.push_back(d.brf.mean);
    brf.error.push_back(d.brf.standard_error);
    radiance.mean.push_back(d.radiance.mean);
    radiance.error.push_back(d.radiance.standard_error);
  }
  return {brf, radiance};
}

// Each band's BRF, direction by direction (the band varying fastest).
Quantity band_quantity(const MeasureRecord& r) {
  Quantity q = r.bottom_of_atmosphere
                   ? Quantity{"band_hdrf",
                              "hemispherical-directional reflectance factor in each band", "1", ""}
                   : Quantity{"band_brf", "bidirectional reflectance factor in each band", "1",
                              "surface_bidirectional_reflectance"};
  for (const renderer::DistantResult& d : r.directions)
    for (std::size_t b = 0; b < r.band_names.size(); ++b) {
      q.mean.push_back(d.band_brf.at(b).mean);
      q.error.push_back(d.band_brf.at(b).standard_error);
    }
  return q;
}

std::vector<Quantity> budget_quantities(const MeasureRecord& r) {
  using Share = renderer::DistantValue renderer::EnergyBudget::*;
  const std::array<std::pair<Share, Quantity>, 10> shares = {{
      {&renderer::EnergyBudget::reflected,
       {"albedo", "reflected share (directional- or bi-hemispherical reflectance)", "1", ""}},
      {&renderer::EnergyBudget::absorbed_leaves,
       {"absorbed_leaves", "share absorbed by leaves and grass (fAPAR in the PAR)", "1", ""}},
      {&renderer::EnergyBudget::absorbed_stems,
       {"absorbed_stems", "share absorbed by trunks and stems", "1", ""}},
      {&renderer::EnergyBudget::absorbed_soil,
       {"absorbed_soil", "share absorbed by the soil", "1", ""}},
      {&renderer::EnergyBudget::absorbed_other,
       {"absorbed_other", "share absorbed by scene objects", "1", ""}},
      {&renderer::EnergyBudget::absorbed_haze,
       {"absorbed_haze", "share absorbed by the haze", "1", ""}},
      {&renderer::EnergyBudget::soil_direct,
       {"soil_direct", "share reaching the soil before any scattering", "1", ""}},
      {&renderer::EnergyBudget::soil_diffuse,
       {"soil_diffuse", "share reaching the soil after scattering", "1", ""}},
      {&renderer::EnergyBudget::lost,
       {"lost", "share cut by the safety limit of legs or bounces", "1", ""}},
      {&renderer::EnergyBudget::total,
       {"total", "reflected, absorbed and lost shares, summed path by path", "1", ""}},
  }};
  std::vector<Quantity> out;
  for (auto [member, q] : shares) {
    for (const auto* b : {&r.budget_sun, &r.budget_isotropic}) {
      if (!b->has_value()) continue;
      q.mean.push_back(((**b).*member).mean);
      q.error.push_back(((**b).*member).standard_error);
    }
    out.push_back(std::move(q));
  }
  return out;
}

void write_values(NetcdfFile& f, const std::vector<std::pair<int, const Quantity*>>& vars) {
  for (std::size_t i = 0; i < vars.size(); i += 2) {
    f.put(vars[i].first, vars[i].second->mean);
    f.put(vars[i + 1].first, vars[i].second->error);
  }
}

}  // namespace

void write_measure_netcdf(const std::filesystem::path& path, const MeasureRecord& r) {
  AtomicFile out(path);
  NetcdfFile f(out.temp_path());
  f.text(NC_GLOBAL, "Conventions", "CF-1.8");
  f.text(NC_GLOBAL, "title", "landsim distant measure of " + r.scenario);
  f.text(NC_GLOBAL, "source", "landsim brf (spectral Monte Carlo path tracer)");
  f.text(NC_GLOBAL, "scenario", r.scenario);
  f.number(NC_GLOBAL, "samples_per_direction", static_cast<double>(r.samples));
  f.text(NC_GLOBAL, "level", r.bottom_of_atmosphere ? "bottom of atmosphere" : "top of atmosphere");
  if (r.bhr) {
    f.number(NC_GLOBAL, "bhr", r.bhr->brf.mean);
    f.number(NC_GLOBAL, "bhr_standard_error", r.bhr->brf.standard_error);
  }

  const int direction = f.dimension("direction", r.directions.size());
  const int zenith = f.variable("sensor_zenith_angle", NC_DOUBLE, {direction});
  const int azimuth = f.variable("sensor_azimuth_angle", NC_DOUBLE, {direction});
  f.text(zenith, "standard_name", "sensor_zenith_angle");
  f.text(azimuth, "standard_name", "sensor_azimuth_angle");
  f.text(azimuth, "comment", "clockwise from north (+y)");
  for (const int v : {zenith, azimuth}) f.text(v, "units", "degree");
  std::string coordinates = "sensor_zenith_angle sensor_azimuth_angle";
  const int relative = f.variable("rami_relative_azimuth_angle", NC_DOUBLE, {direction});
  f.text(relative, "long_name",
         "view azimuth relative to the sun's, counter-clockwise seen from above (RAMI's frame: "
         "the sun's azimuth 0)");
  f.text(relative, "units", "degree");
  coordinates += " rami_relative_azimuth_angle";
  int signed_zenith = -1;
  if (!r.signed_view_zenith_deg.empty()) {
    signed_zenith = f.variable("view_zenith_principal_plane", NC_DOUBLE, {direction});
    f.text(signed_zenith, "long_name",
           "view zenith in the principal plane, negative on the sun's side");
    f.text(signed_zenith, "units", "degree");
    coordinates += " view_zenith_principal_plane";
  }
  const int sun_zenith = f.variable("solar_zenith_angle", NC_DOUBLE, {});
  const int sun_azimuth = f.variable("solar_azimuth_angle", NC_DOUBLE, {});
  f.text(sun_zenith, "standard_name", "solar_zenith_angle");
  f.text(sun_azimuth, "standard_name", "solar_azimuth_angle");
  for (const int v : {sun_zenith, sun_azimuth}) f.text(v, "units", "degree");

  std::vector<std::pair<int, const Quantity*>> vars;
  const std::vector<Quantity> per_direction = direction_quantities(r);
  for (const Quantity& q : per_direction) define(f, q, {direction}, coordinates, vars);
  int band_names = -1;
  std::optional<Quantity> bands;
  if (!r.band_names.empty()) {
    const int band = f.dimension("band", r.band_names.size());
    band_names = f.variable("band", NC_STRING, {band});
    f.text(band_names, "long_name", "[[bands]] band name");
    bands = band_quantity(r);
    define(f, *bands, {direction, band}, coordinates, vars);
  }
  int illumination_names = -1;
  std::vector<Quantity> budget;
  std::vector<std::string> lights;
  if (r.budget_sun) lights.push_back("sun");
  if (r.budget_isotropic) lights.push_back("isotropic");
  if (!lights.empty()) {
    const int illumination = f.dimension("illumination", lights.size());
    illumination_names = f.variable("illumination", NC_STRING, {illumination});
    f.text(illumination_names, "long_name",
           "the light the budget follows: the sun's beam, or an isotropic sky");
    budget = budget_quantities(r);
    for (const Quantity& q : budget) define(f, q, {illumination}, "", vars);
    f.number(NC_GLOBAL, "budget_paths", static_cast<double>(r.budget_paths));
  }
  f.end_definitions();

  std::vector<double> zeniths, azimuths, relatives;
  for (const renderer::DistantResult& d : r.directions) {
    zeniths.push_back(d.direction.zenith_deg);
    azimuths.push_back(d.direction.azimuth_deg);
    relatives.push_back(
        renderer::rami_relative_azimuth(d.direction.azimuth_deg, r.sun_azimuth_deg));
  }
  f.put(zenith, zeniths);
  f.put(azimuth, azimuths);
  f.put(relative, relatives);
  if (signed_zenith >= 0) f.put(signed_zenith, r.signed_view_zenith_deg);
  f.put(sun_zenith, std::vector<double>{r.sun_zenith_deg});
  f.put(sun_azimuth, std::vector<double>{r.sun_azimuth_deg});
  if (band_names >= 0) f.put(band_names, r.band_names);
  if (illumination_names >= 0) f.put(illumination_names, lights);
  write_values(f, vars);
  f.close();
  out.commit();
}

}  // namespace landsim::exporters
