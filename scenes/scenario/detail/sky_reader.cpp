#include "scenes/scenario/detail/sky_reader.h"

#include "params/table_reader.h"
#include "scenes/scenario/detail/toml_tables.h"
#include "scenes/scenario/solar_position.h"

namespace landsim::scenes::detail {

namespace {

using params::Range;
using params::TableReader;

// The sun from date, time and place: TOML's own date and time values.
void read_sun_by_date(TableReader& r, const toml::table& t, SunSettings& s) {
  const toml::node* date = t.get("date");
  const toml::node* time = t.get("time");
  if (date == nullptr || !date->is_date())
    r.fail("date", "expected a TOML date such as 2026-06-21");
  if (time == nullptr || !time->is_time()) r.fail("time", "expected a TOML time such as 10:30:00");
  r.allow("date");  // their types were checked above
  r.allow("time");
  const toml::date d = *date->value<toml::date>();
  const toml::time tm = *time->value<toml::time>();
  const double latitude = r.number("latitude", Range{-90.0, 90.0});
  const double longitude = r.number("longitude", Range{-180.0, 180.0});
  const double offset = r.number("utc_offset", Range{-14.0, 14.0}, 0.0);
  const double hour = tm.hour + tm.minute / 60.0 + tm.second / 3600.0 - offset;
  const SolarPosition p = solar_position(d.year, d.month, d.day, hour, latitude, longitude);
  if (p.elevation_deg <= 0.0) {
    r.fail("time", "the sun is below the horizon then (elevation " +
                       std::to_string(p.elevation_deg) + " degrees)");
  }
  s.elevation_deg = p.elevation_deg;
  s.azimuth_deg = p.azimuth_deg;
  s.day_of_year = p.day_of_year;
}

}  // namespace

SunSettings read_sun(const toml::table& t, const std::string& file) {
  TableReader r(t, "sun", file);
  SunSettings s;
  if (r.has("date") || r.has("time")) {
    if (r.has("elevation") || r.has("azimuth"))
      r.fail("date", "give either elevation and azimuth, or date, time, latitude and longitude");
    read_sun_by_date(r, t, s);
  } else {
    s.elevation_deg = r.number("elevation", Range{0.0, 90.0, true});
    s.azimuth_deg = r.number("azimuth", Range{0.0, 360.0});
    for (const char* k : {"latitude", "longitude", "utc_offset"}) {
      if (r.has(k)) r.fail(k, "only used with date and time (instead of elevation and azimuth)");
    }
  }
  // Lux (linear Rec. 709, Y the illuminance): 1e6 is ten times the brightest real sun.
  if (r.has("irradiance")) s.irradiance = to_vec3f(r.vec3("irradiance", Range{0.0, 1e6}));
  r.finish();
  return s;
}

renderer::Sky read_sky(const toml::table& t, const std::string& file) {
  TableReader r(t, "sky", file);
  renderer::Sky s;
  const std::string model = r.choice(
      "model", {"hosek-wilkie", "preetham", "gradient", "none", "atmosphere"}, "hosek-wilkie");
  // "none": the collimated sun alone, as radiative-transfer benchmarks light a scene (RAMI).
  // "atmosphere": the sky is the one atmosphere's light ([atmosphere], docs/ATMOSPHERE.md).
  s.model = model == "hosek-wilkie" ? renderer::SkyKind::hosek_wilkie
            : model == "preetham"   ? renderer::SkyKind::preetham
            : model == "none"       ? renderer::SkyKind::none
            : model == "atmosphere" ? renderer::SkyKind::atmosphere
                                    : renderer::SkyKind::gradient;
  // Hosek-Wilkie's tables span turbidity 1-10; Preetham's fit is not valid below 1.7.
  s.turbidity = r.number(
      "turbidity", Range{s.model == renderer::SkyKind::preetham ? 1.7 : 1.0, 10.0}, s.turbidity);
  // The gradient's two colours (cd/m2, linear Rec. 709): equal, a uniform sky, the isotropic
  // light of radiative-transfer benchmarks (DISORT's FISOT).
  for (const char* key : {"zenith_radiance", "horizon_radiance"})
    if (r.has(key) && s.model != renderer::SkyKind::gradient)
      r.fail(key, "only with model = \"gradient\"");
  s.zenith_radiance = to_vec3f(r.vec3("zenith_radiance", Range{0.0, 1e6}, Vec3(s.zenith_radiance)));
  s.horizon_radiance =
      to_vec3f(r.vec3("horizon_radiance", Range{0.0, 1e6}, Vec3(s.horizon_radiance)));
  r.finish();
  return s;
}

}  // namespace landsim::scenes::detail
