#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <set>
#include <sstream>

#include "core/fnv_hash.h"
#include "core/input_error.h"
#include "featuremaps/placement.h"
#include "params/table_reader.h"
#include "scenes/scenario.h"

#include "scenes/detail/relative_path.h"
#include "scenes/detail/scenario_overrides.h"
#include "scenes/detail/sensor_reader.h"
#include "scenes/detail/view_reader.h"
#include "scenes/sensor_bands.h"
#include "scenes/solar_position.h"
#include "terrain/raster_files.h"

namespace landsim::scenes {
namespace {

using detail::resolve;
using params::Range;
using params::TableReader;

constexpr Range kUnit{0.0, 1.0};
constexpr Range kPositive{0.0, 1e12, true};

Vec3f to_vec3f(const Vec3& v) { return Vec3f(v); }

// Returns the sub-table `name`, or an empty one when absent; refuses a non-table.
const toml::table& sub_table(const toml::table& root, std::string_view name,
                             const std::string& file, bool required) {
  static const toml::table kEmpty;
  const toml::node* n = root.get(name);
  if (n == nullptr) {
    if (required)
      throw InputError(file + ": required table [" + std::string(name) + "] is missing");
    return kEmpty;
  }
  if (!n->is_table()) {
    const auto& b = n->source().begin;
    throw InputError(file + ":" + std::to_string(b.line) + ":" + std::to_string(b.column) + ": " +
                     std::string(name) + ": expected a table, got " + params::type_name(*n));
  }
  return *n->as_table();
}

// [terrain] context: coarser elevation rasters around the grid, each checked to exist.
std::vector<std::string> read_context(TableReader& r, const std::string& base_dir,
                                      std::vector<std::string>& locations) {
  std::vector<std::string> paths;
  const toml::node* n =
      r.value("context", "an array of raster files: coarser elevation grids around the grid", "[]");
  if (n == nullptr) return paths;
  const toml::array* files = n->as_array();
  if (files == nullptr)
    r.fail_at(*n, "context", "expected an array of file names, such as [\"region.tif\"]");
  for (const toml::node& f : *files) {
    if (!f.is_string()) r.fail_at(f, "context", "expected a file name (a string)");
    paths.push_back(resolve(base_dir, *f.value<std::string>()));
    locations.push_back(r.location(&f));
    if (!terrain::raster_file_exists(paths.back()))
      r.fail_at(f, "context", "file not found: " + paths.back());
  }
  return paths;
}

TerrainSettings read_terrain(const toml::table& t, const std::string& file,
                             const std::string& base_dir) {
  TableReader r(t, "terrain", file);
  TerrainSettings s;
  s.elevation = resolve(base_dir, r.string("elevation"));
  if (!terrain::raster_file_exists(s.elevation)) {
    r.fail("elevation", "file not found: " + s.elevation);
  }
  s.dem.cell_size = r.optional_number("cell_size", kPositive);
  if (const auto o = r.optional_numbers("origin", 2, Range{-1e12, 1e12})) {
    s.dem.origin = std::array<double, 2>{(*o)[0], (*o)[1]};
  }
  s.dem.height_scale = r.number("height_scale", Range{-1e6, 1e6}, s.dem.height_scale);
  if (s.dem.height_scale == 0.0) r.fail("height_scale", "expected a non-zero number, got 0");
  s.dem.height_offset = r.number("height_offset", Range{-1e6, 1e6}, s.dem.height_offset);
  const std::string nodata = r.choice("nodata", {"hole", "fill"}, "hole");
  s.dem.nodata = nodata == "fill" ? terrain::NodataPolicy::fill : terrain::NodataPolicy::hole;
  s.albedo = to_vec3f(r.vec3("albedo", kUnit, Vec3(s.albedo)));
  s.context = read_context(r, base_dir, s.context_locations);
  r.finish();
  return s;
}

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
}

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
  const std::string model =
      r.choice("model", {"hosek-wilkie", "preetham", "gradient"}, "hosek-wilkie");
  s.model = model == "hosek-wilkie" ? renderer::SkyKind::hosek_wilkie
            : model == "preetham"   ? renderer::SkyKind::preetham
                                    : renderer::SkyKind::gradient;
  // Hosek-Wilkie's tables span turbidity 1-10; Preetham's fit is not valid below 1.7.
  s.turbidity = r.number(
      "turbidity", Range{s.model == renderer::SkyKind::preetham ? 1.7 : 1.0, 10.0}, s.turbidity);
  r.finish();
  return s;
}

// An array of numbers (at least `least`, at most `most`), each in `range`; empty when absent.
std::vector<double> number_list(TableReader& r, std::string_view key, std::size_t least,
                                std::size_t most, Range range) {
  const toml::node* n = r.value(key, "an array of numbers");
  if (n == nullptr) return {};
  const toml::array* a = n->as_array();
  if (a == nullptr || a->size() < least || a->size() > most)
    r.fail_at(*n, key, "expected an array of " + std::to_string(least) + " to " +
                           std::to_string(most) + " numbers");
  std::vector<double> out;
  for (const toml::node& e : *a) {
    const std::optional<double> v = e.value<double>();
    if (!v || !range.contains(*v)) r.fail_at(e, key, "expected numbers " + range.describe());
    out.push_back(*v);
  }
  return out;
}

// [haze]'s phase function: Henyey-Greenstein by default, or isotropic, Rayleigh, a table by
// scattering angle, or Legendre moments.
void read_phase(TableReader& r, renderer::Haze& h) {
  const std::string phase =
      r.choice("phase", {"henyey-greenstein", "isotropic", "rayleigh", "table", "legendre"},
               "henyey-greenstein");
  h.asymmetry = r.number("asymmetry", Range{-0.95, 0.95}, h.asymmetry);
  // Bounded: a table is evaluated by bisection, a Legendre series summed at 4001 cosines.
  h.phase_angles = number_list(r, "phase_angles", 2, 100000, Range{0.0, 180.0});
  h.phase_values = number_list(r, "phase_values", 2, 100000, Range{0.0, 1e12});
  h.phase_moments = number_list(r, "phase_moments", 1, 1000, Range{-1.0, 1.0});
  if (phase == "table") {
    h.phase = renderer::AerosolPhase::table;
    if (h.phase_angles.empty() || h.phase_angles.size() != h.phase_values.size())
      r.fail("phase_angles", "phase = \"table\" needs phase_angles and as many phase_values");
    for (std::size_t i = 1; i < h.phase_angles.size(); ++i)
      if (!(h.phase_angles[i] > h.phase_angles[i - 1]))
        r.fail("phase_angles", "expected increasing angles");
    if (h.phase_angles.front() != 0.0 || h.phase_angles.back() != 180.0)
      r.fail("phase_angles", "expected angles from 0 to 180 degrees");
  } else if (phase == "legendre") {
    h.phase = renderer::AerosolPhase::legendre;
    if (h.phase_moments.empty() || h.phase_moments.front() != 1.0)
      r.fail("phase_moments", "phase = \"legendre\" needs phase_moments starting with 1");
  } else {
    h.phase = phase == "isotropic"  ? renderer::AerosolPhase::isotropic
              : phase == "rayleigh" ? renderer::AerosolPhase::rayleigh
                                    : renderer::AerosolPhase::henyey_greenstein;
  }
}

renderer::Haze read_haze(const toml::table& root, const std::string& file) {
  renderer::Haze h;
  if (!root.contains("haze")) return h;
  TableReader r(sub_table(root, "haze", file, true), "haze", file);
  h.enabled = true;
  if (r.has("layer")) {
    // The plane-parallel layer of the radiative-transfer checks (docs/ATMOSPHERE.md).
    TableReader layer = r.table("layer");
    renderer::HazeLayer l;
    l.optical_depth = layer.number("optical_depth", Range{1e-6, 1e3});
    l.top = layer.number("top", Range{1e-3, 1e6}, l.top);
    layer.finish();
    h.layer = l;
    h.molecular = false;
  } else {
    h.visibility = r.number("visibility", Range{10.0, 1e7});
    h.scale_height = r.number("scale_height", Range{10.0, 1e5}, h.scale_height);
    h.angstrom = r.number("angstrom", Range{-1.0, 4.0}, h.angstrom);
    h.molecular = r.boolean("molecular", h.molecular);
  }
  // The haze's light other than the sun's single scattering: tabulated by default, traced
  // with `paths` (the plane-parallel layer of the checks: traced unless told).
  const std::string light =
      r.choice("multiple_scattering", {"table", "paths"}, h.layer ? "paths" : "table");
  h.scattering =
      light == "paths" ? renderer::HazeScattering::paths : renderer::HazeScattering::table;
  if (r.has("colour") && r.has("single_scattering_albedo"))
    r.fail("single_scattering_albedo", "give either colour or single_scattering_albedo");
  h.albedo = to_vec3f(r.vec3("colour", kUnit, Vec3(h.albedo)));
  if (const auto a = r.optional_number("single_scattering_albedo", Range{0.0, 1.0}))
    h.albedo = Vec3f{static_cast<float>(*a), static_cast<float>(*a), static_cast<float>(*a)};
  read_phase(r, h);
  r.finish();
  return h;
}

std::vector<ViewSettings> read_views(const toml::table& root, const std::string& file,
                                     const std::optional<SensorSettings>& sensor) {
  const toml::node* n = root.get("views");
  if (n == nullptr) throw InputError(file + ": at least one [[views]] table is required");
  const toml::array* a = n->as_array();
  if (a == nullptr || a->empty() || !a->is_array_of_tables()) {
    const auto& b = n->source().begin;
    throw InputError(file + ":" + std::to_string(b.line) + ":" + std::to_string(b.column) +
                     ": views: expected one or more [[views]] tables");
  }
  std::vector<ViewSettings> views;
  std::set<std::string> names;
  for (std::size_t i = 0; i < a->size(); ++i) {
    // A view is named by its name in messages once it has one.
    const auto name = a->get(i)->as_table()->get("name");
    const std::optional<std::string> text = name ? name->value<std::string>() : std::nullopt;
    const std::string path = text ? "views \"" + *text + "\"" : "views[" + std::to_string(i) + "]";
    views.push_back(detail::read_view(*a->get(i)->as_table(), path, file, sensor));
    const TableReader located(*a->get(i)->as_table(), path, file);
    views.back().location = located.location(a->get(i)->as_table()->get("position"));
    if (!names.insert(views.back().name).second) {
      TableReader(*a->get(i)->as_table(), path, file)
          .fail("name", "duplicate view name \"" + views.back().name + "\"");
    }
  }
  return views;
}

// "auto", or an exposure value at ISO 100: -6 (a moonlit night) to 24 (beyond any sunlit
// scene), the range a photographer's exposure table spans.
std::optional<double> read_exposure(TableReader& r) {
  const toml::node* n = r.value("exposure", "\"auto\" or an EV100 from -6 to 24", "\"auto\"");
  if (n == nullptr) return std::nullopt;
  if (const auto* s = n->as_string(); s != nullptr && s->get() == "auto") return std::nullopt;
  if (const auto* s = n->as_string())
    r.fail_at(*n, "exposure",
              "expected \"auto\" or an EV100 from -6 to 24, got \"" + s->get() + "\"");
  if (!n->is_number()) r.fail_at(*n, "exposure", "expected \"auto\" or an EV100 from -6 to 24");
  const double ev = n->value<double>().value_or(0.0);
  if (!(ev >= -6.0 && ev <= 24.0))
    r.fail_at(*n, "exposure",
              fmt::format("expected \"auto\" or an EV100 from -6 to 24, got {}", ev));
  return ev;
}

// [render] formats: "exr" (always written: the set's own record) and optionally "geotiff",
// "envi".
void read_formats(TableReader& r, RenderSection& s) {
  const toml::node* n =
      r.value("formats", "an array of \"exr\", \"geotiff\", \"envi\"", "[\"exr\"]");
  if (n == nullptr) return;
  const toml::array* a = n->as_array();
  if (a == nullptr) r.fail_at(*n, "formats", "expected an array such as [\"exr\", \"geotiff\"]");
  bool exr = false;
  for (const toml::node& f : *a) {
    const std::optional<std::string> name = f.value<std::string>();
    if (!name || (*name != "exr" && *name != "geotiff" && *name != "envi"))
      r.fail_at(f, "formats", "expected \"exr\", \"geotiff\" or \"envi\"");
    exr |= *name == "exr";
    s.geotiff |= *name == "geotiff";
    s.envi |= *name == "envi";
  }
  if (!exr)
    r.fail_at(*n, "formats",
              "must include \"exr\" (the image set's own record, read by --resume "
              "and compare)");
}

RenderSection read_render(const toml::table& t, const std::string& file) {
  TableReader r(t, "render", file);
  RenderSection s;
  s.spp = static_cast<int>(r.integer("spp", 1, kMaxSpp, s.spp));
  s.noise_threshold = r.number("noise_threshold", Range{0.0, 1.0}, s.noise_threshold);
  if (r.has("min_spp")) {
    if (!(s.noise_threshold > 0.0))
      r.fail("min_spp", "is for adaptive sampling: give noise_threshold (above 0) too");
    s.min_spp = static_cast<int>(r.integer("min_spp", 1, s.spp));
  }
  s.seed = static_cast<std::uint64_t>(r.integer("seed", 0, INT64_MAX, s.seed));
  const char* sampler = s.sampler == SampleSequence::sobol ? "sobol" : "independent";
  s.sampler = r.choice("sampler", {"independent", "sobol"}, sampler) == "sobol"
                  ? SampleSequence::sobol
                  : SampleSequence::independent;
  if (r.has("sampling_seed"))
    s.sampling_seed = static_cast<std::uint64_t>(r.integer("sampling_seed", 0, INT64_MAX));
  s.threads = static_cast<int>(r.integer("threads", 0, 1024, s.threads));
  s.max_bounces = static_cast<int>(r.integer("max_bounces", -1, 1000000, s.max_bounces));
  s.exposure_ev100 = read_exposure(r);
  s.checkpoint_seconds = r.number("checkpoint_seconds", Range{0.0, 1e6}, s.checkpoint_seconds);
  s.season = *trees::season_from_name(
      r.choice("season", {"spring", "summer", "autumn", "winter"}, "summer"));
  s.degradation = r.boolean("degradation", s.degradation);
  s.quality = r.number("quality", Range{0.0, 1.0, true, false}, s.quality);
  s.max_memory = r.byte_size("max_memory");
  s.reflectance = r.boolean("reflectance", s.reflectance);
  read_formats(r, s);
  if (r.has("frames")) {
    const toml::node* n = t.get("frames");
    const toml::array* a = n->as_array();
    if (a == nullptr || a->empty() || a->size() > static_cast<std::size_t>(kMaxFrames)) {
      r.fail("frames",
             "expected an array of 1 to " + std::to_string(kMaxFrames) + " times in seconds");
    }
    s.frames = r.numbers("frames", a->size(), Range{0.0, 1e9});
  } else {
    r.numbers("frames", 1, Range{0.0, 1e9}, std::vector<double>{0.0});
  }
  r.finish();
  return s;
}

WindSettings read_wind(const toml::table& t, const std::string& file) {
  TableReader r(t, "wind", file);
  WindSettings w;
  w.speed = r.number("speed", Range{0.0, kMaxWindSpeed}, w.speed);
  w.gust = r.number("gust", Range{0.0, kMaxWindSpeed}, w.gust);
  w.direction_deg = r.number("direction", Range{0.0, 360.0}, w.direction_deg);
  w.gust_scale = r.number("gust_scale", Range{1.0, 100000.0}, w.gust_scale);
  w.phase_groups = static_cast<int>(r.integer("phase_groups", 1, 16, w.phase_groups));
  r.finish();
  return w;
}

std::optional<FeatureMapSettings> read_featuremaps(const toml::table& root, const std::string& file,
                                                   const std::string& base_dir) {
  if (!root.contains("featuremaps")) return std::nullopt;
  TableReader r(sub_table(root, "featuremaps", file, true), "featuremaps", file);
  FeatureMapSettings f;
  // An optional path key: resolved against the scenario, checked to exist.
  const auto path = [&](std::string_view key) -> std::string {
    r.allow(key);
    if (!r.has(key)) return {};
    const std::string p = resolve(base_dir, r.string(key));
    if (!terrain::raster_file_exists(p)) r.fail(key, "file not found: " + p);
    return p;
  };
  f.vegetation = path("vegetation");
  f.classes = path("classes");
  f.class_map = path("class_map");
  f.soil = path("soil");
  f.rock = path("rock");
  f.water = path("water");
  f.road = path("road");
  f.placement.cell_size = r.optional_number("cell_size", kPositive);
  if (const auto o = r.optional_numbers("origin", 2, Range{-1e12, 1e12})) {
    f.placement.origin = std::array<double, 2>{(*o)[0], (*o)[1]};
  }
  if (!f.vegetation.empty() && !f.classes.empty()) {
    r.fail("vegetation",
           "give either vegetation (a 16-bit map) or classes with class_map, not both");
  }
  if (!f.classes.empty() && f.class_map.empty()) r.fail("class_map", "required with classes");
  r.finish();
  return f;
}

// An optional array of tables ([[key]]): null when absent, refused when something else.
const toml::array* tables(const toml::table& root, std::string_view key, const std::string& file) {
  const toml::node* n = root.get(key);
  if (n == nullptr) return nullptr;
  const toml::array* a = n->as_array();
  if (a == nullptr || !a->is_array_of_tables()) {
    const auto& b = n->source().begin;
    throw InputError(file + ":" + std::to_string(b.line) + ":" + std::to_string(b.column) + ": " +
                     std::string(key) + ": expected [[" + std::string(key) + "]] tables");
  }
  return a;
}

// The optional `age` of a [[species]] table: years, or [youngest, oldest] across variants
// (every core; trees/tree_age.h, docs/SPECIES.md "Age").
void read_age(TableReader& r, const toml::table& t, SpeciesSettings& s) {
  r.allow("age");
  const toml::node* n = t.get("age");
  if (n == nullptr) return;
  const auto years = [&](const toml::node& v) {
    const auto x = v.value<double>();
    if (!x || !(*x >= 0.0 && *x <= 500.0))
      r.fail("age", "expected years from 0 to 500, or [youngest, oldest]");
    return *x;
  };
  if (const toml::array* range = n->as_array()) {
    if (range->size() != 2) r.fail("age", "expected [youngest, oldest]");
    s.age_min = years(*range->get(0));
    s.age_max = years(*range->get(1));
    if (s.age_max < s.age_min) r.fail("age", "expected [youngest, oldest] with youngest first");
  } else {
    s.age_min = s.age_max = years(*n);
  }
}

// cover = "everywhere" | a fraction in (0, 1] | { rectangle = [x0, y0, x1, y1] } |
// { polygon = [[x, y], ...] }, terrain coordinates.
featuremaps::Cover read_cover(TableReader& r) {
  constexpr const char* kExpected =
      "expected \"everywhere\", a fraction of the terrain in (0, 1], { rectangle = [west, "
      "south, east, north] } or { polygon = [[x, y], ...] } in terrain coordinates";
  const toml::node* n = r.value("cover", kExpected);
  featuremaps::Cover c;
  if (const auto* s = n->as_string()) {
    if (s->get() != "everywhere")
      r.fail_at(*n, "cover", std::string(kExpected) + ", got \"" + s->get() + "\"");
    return c;
  }
  if (n->is_number()) {
    c.kind = featuremaps::Cover::Kind::fraction;
    c.fraction = n->value<double>().value_or(0.0);
    if (!(c.fraction > 0.0 && c.fraction <= 1.0))
      r.fail_at(*n, "cover", fmt::format("{}, got {}", kExpected, c.fraction));
    return c;
  }
  const toml::table* t = n->as_table();
  if (t == nullptr || t->size() != 1 || !(t->contains("rectangle") || t->contains("polygon")))
    r.fail_at(*n, "cover", kExpected);
  c.kind = featuremaps::Cover::Kind::polygon;
  const toml::array* a = t->get_as<toml::array>(t->contains("rectangle") ? "rectangle" : "polygon");
  const auto number = [&](const toml::node* v) {
    if (v == nullptr || !v->is_number()) r.fail_at(*n, "cover", kExpected);
    return v->value<double>().value_or(0.0);
  };
  if (a == nullptr) r.fail_at(*n, "cover", kExpected);
  if (t->contains("rectangle")) {
    if (a->size() != 4) r.fail_at(*n, "cover", "rectangle: expected [west, south, east, north]");
    const double w = number(a->get(0)), s = number(a->get(1)), e = number(a->get(2)),
                 no = number(a->get(3));
    if (!(e > w && no > s))
      r.fail_at(*n, "cover", "rectangle: expected east > west and north > south");
    c.polygon = {{w, s}, {e, s}, {e, no}, {w, no}};
    return c;
  }
  for (const toml::node& v : *a) {
    const toml::array* p = v.as_array();
    if (p == nullptr || p->size() != 2) r.fail_at(*n, "cover", "polygon: expected [[x, y], ...]");
    c.polygon.push_back({number(p->get(0)), number(p->get(1))});
  }
  if (c.polygon.size() < 3) r.fail_at(*n, "cover", "polygon: expected at least 3 corners");
  return c;
}

// Fraction covers share the terrain out: together at most all of it.
template <typename Settings>
void check_fractions(const std::vector<Settings>& items, const toml::array& tables,
                     const std::string& name, const std::string& file) {
  double total = 0.0;
  for (std::size_t i = 0; i < items.size(); ++i) {
    if (!items[i].cover || items[i].cover->kind != featuremaps::Cover::Kind::fraction) continue;
    total += items[i].cover->fraction;
    if (total > 1.0 + 1e-9) {
      TableReader r(*tables.get(i)->as_table(), name + "[" + std::to_string(i) + "]", file);
      r.fail("cover", fmt::format("the fractions of the [[{}]] covers add up to {:.3g}; "
                                  "expected at most 1 (they share the terrain out)",
                                  name, total));
    }
  }
}

std::vector<SpeciesSettings> read_species(const toml::table& root, const std::string& file,
                                          const std::string& base_dir) {
  std::vector<SpeciesSettings> out;
  const toml::array* a = tables(root, "species", file);
  if (a == nullptr) return out;
  std::set<int> bits;
  for (std::size_t i = 0; i < a->size(); ++i) {
    TableReader r(*a->get(i)->as_table(), "species[" + std::to_string(i) + "]", file);
    SpeciesSettings s;
    s.location = r.location(nullptr);
    s.bit = static_cast<int>(r.integer("bit", 0, featuremaps::kTreeBits - 1));
    if (!bits.insert(s.bit).second)
      r.fail("bit", "species bit " + std::to_string(s.bit) + " is used twice");
    const std::string species_file = resolve(base_dir, r.string("file"));
    const std::optional<std::string> text = terrain::read_text_file(species_file);
    if (!text) r.fail("file", "species file not found: " + species_file);
    s.species = trees::parse_species(*text, species_file);
    if (r.has("leaf_optics")) {
      TableReader optics = r.table("leaf_optics");
      s.species.colours.leaf_optics = trees::read_leaf_contents(optics);
    }
    s.variants = static_cast<int>(r.integer("variants", 1, 256, s.variants));
    s.density_per_ha = r.number("density_per_ha", Range{0.0, 100000.0, true}, s.density_per_ha);
    s.scale_variation = r.number("scale_variation", Range{0.0, 0.9}, s.scale_variation);
    s.colour_variation = r.number("colour_variation", Range{0.0, 0.9}, s.colour_variation);
    s.min_spacing = r.number("min_spacing", Range{0.0, 1000.0}, s.min_spacing);
    // Trees stand on a jittered grid of one tree per spacing^2 (featuremaps/placement.h).
    if (const double grid = featuremaps::grid_spacing(s.density_per_ha); s.min_spacing > grid)
      r.fail("min_spacing", fmt::format("expected at most the grid spacing {:.3g} m of "
                                        "density_per_ha {} (one tree per {:.3g} m square), got {}",
                                        grid, s.density_per_ha, grid, s.min_spacing));
    if (r.has("bark_texture")) {
      s.bark_texture = resolve(base_dir, r.string("bark_texture"));
      if (!terrain::raster_file_exists(s.bark_texture))
        r.fail("bark_texture", "file not found: " + s.bark_texture);
    }
    r.allow("bark_texture");
    read_age(r, *a->get(i)->as_table(), s);
    s.evergreen = r.boolean("evergreen", s.evergreen);
    if (r.has("cover")) s.cover = read_cover(r);
    r.finish();
    out.push_back(std::move(s));
  }
  check_fractions(out, *a, "species", file);
  return out;
}

std::vector<GrassSettings> read_grass(const toml::table& root, const std::string& file) {
  std::vector<GrassSettings> out;
  const toml::array* a = tables(root, "grass", file);
  if (a == nullptr) return out;
  std::set<int> types;
  for (std::size_t i = 0; i < a->size(); ++i) {
    TableReader r(*a->get(i)->as_table(), "grass[" + std::to_string(i) + "]", file);
    GrassSettings g;
    g.location = r.location(nullptr);
    g.type = static_cast<int>(r.integer("type", 1, 3));
    if (!types.insert(g.type).second)
      r.fail("type", "grass type " + std::to_string(g.type) + " is defined twice");
    g.density_per_m2 = r.number("density_per_m2", Range{0.0, 2000.0, true}, g.density_per_m2);
    g.blade_length = r.number("blade_length", Range{0.01, 3.0}, g.blade_length);
    g.blade_width = r.number("blade_width", Range{0.0005, 0.05}, g.blade_width);
    g.curvature = r.number("curvature", Range{0.0, 1.0}, g.curvature);
    g.colour = to_vec3f(r.vec3("colour", kUnit, Vec3{0.10, 0.22, 0.05}));
    if (r.has("cover")) g.cover = read_cover(r);
    r.finish();
    out.push_back(g);
  }
  check_fractions(out, *a, "grass", file);
  return out;
}

// Ground material names in [ground] and their ids (renderer/materials/ground_shading.h); "grass" is
// the ground under all three grass types.
const std::vector<std::pair<std::string, std::vector<int>>> kGroundNames{
    {"terrain", {0}}, {"road", {1}},        {"water", {2}},       {"rock", {3}},
    {"soil", {4}},    {"grass", {5, 6, 7}}, {"surroundings", {8}}};

// The ids of the material named `name` (a value, or a table key when `name` is given), with
// `n` locating the message.
std::vector<int> ground_ids(const TableReader& r, const toml::node& n, std::string_view key,
                            std::optional<std::string> name = std::nullopt) {
  if (!name) name = n.value<std::string>();
  for (const auto& [known, ids] : kGroundNames)
    if (name && *name == known) return ids;
  r.fail_at(n, key,
            "unknown ground material " + (name ? "'" + *name + "'" : params::type_name(n)) +
                " (expected terrain, road, water, rock, soil, grass or surroundings)");
}

// A number for every material but water, or { material = number, ... }: `key` of [ground].
void read_per_material(TableReader& r, std::string_view key, const std::string& expected,
                       const std::string& fallback, Range range,
                       std::array<float, renderer::kGroundMaterials>& out) {
  const toml::node* n = r.value(key, expected, fallback);
  if (n == nullptr) return;
  const auto number = [&](const toml::node& v) {
    const std::optional<double> f = v.value<double>();
    if (!f || !range.contains(*f)) r.fail_at(v, key, "expected " + range.describe());
    return static_cast<float>(*f);
  };
  if (const toml::table* t = n->as_table()) {
    for (auto&& [name, value] : *t)
      for (int id : ground_ids(r, value, key, std::string(name.str())))
        out[static_cast<std::size_t>(id)] = number(value);
    return;
  }
  const float f = number(*n);
  for (std::size_t id = 0; id < out.size(); ++id)
    if (id != 2) out[id] = f;
}

renderer::GroundRule read_rule(TableReader& r) {
  renderer::GroundRule rule;
  const std::string m = r.choice("measure", {"slope", "height", "sun_facing"});
  rule.measure = m == "slope"    ? renderer::TerrainMeasure::slope
                 : m == "height" ? renderer::TerrainMeasure::height
                                 : renderer::TerrainMeasure::sun_facing;
  const Range any{-1e7, 1e7};
  if (const auto a = r.optional_number("above", any)) rule.above = *a;
  if (const auto b = r.optional_number("below", any)) rule.below = *b;
  if (!r.has("above") && !r.has("below")) r.fail("measure", "give above, below or both");
  rule.softness = r.number("softness", Range{0.0, 1e6}, rule.softness);
  const toml::node* on = r.value("on", "an array of ground material names",
                                 "[\"terrain\", \"soil\", \"rock\", \"grass\", \"surroundings\"]");
  if (on == nullptr) {
    rule.on = 0b111111001;  // all but road and water
  } else if (const toml::array* a = on->as_array()) {
    for (const toml::node& n : *a)
      for (int id : ground_ids(r, n, "on")) rule.on |= static_cast<std::uint16_t>(1u << id);
  } else {
    r.fail_at(*on, "on", "expected an array of ground material names");
  }
  if (const toml::node* to = r.value("becomes", "a ground material name", "")) {
    const std::vector<int> ids = ground_ids(r, *to, "becomes");
    rule.becomes = ids.front();
  }
  rule.tint = to_vec3f(r.vec3("tint", Range{0.0, 4.0}, Vec3{1.0, 1.0, 1.0}));
  if (rule.becomes < 0 && !r.has("tint"))
    r.fail("measure", "a rule must change something: give becomes, tint or both");
  r.finish();
  return rule;
}

// textures = { rock = "rock.jpg", soil = "soil.png" }: files checked to exist.
void read_textures(TableReader& r, const std::string& base_dir, GroundMaterials& g) {
  const toml::node* n = r.value("textures", "a table of material = image file", "");
  if (n == nullptr) return;
  const toml::table* t = n->as_table();
  if (t == nullptr) r.fail_at(*n, "textures", "expected a table such as { rock = \"rock.jpg\" }");
  for (auto&& [name, value] : *t) {
    if (!value.is_string()) r.fail_at(value, "textures", "expected an image file name");
    const std::string path = resolve(base_dir, *value.value<std::string>());
    if (!terrain::raster_file_exists(path)) r.fail_at(value, "textures", "file not found: " + path);
    for (int id : ground_ids(r, value, "textures", std::string(name.str()))) {
      g.texture_files[static_cast<std::size_t>(id)] = path;
      g.texture_locations[static_cast<std::size_t>(id)] = r.location(&value);
    }
  }
}

GroundMaterials read_ground(const toml::table& root, const std::string& file,
                            const std::string& base_dir) {
  GroundMaterials g;
  TableReader r(sub_table(root, "ground", file, false), "ground", file);
  g.soil = to_vec3f(r.vec3("soil", kUnit, Vec3(g.soil)));
  g.rock = to_vec3f(r.vec3("rock", kUnit, Vec3(g.rock)));
  g.water = to_vec3f(r.vec3("water", kUnit, Vec3(g.water)));
  g.road = to_vec3f(r.vec3("road", kUnit, Vec3(g.road)));
  g.soil_moisture = r.number("soil_moisture", kUnit, g.soil_moisture);
  read_per_material(r, "variation", "a fraction 0-1, or a table of material = fraction",
                    "0.15 (road 0.05, rock 0.2, water 0)", kUnit, g.shading.variation);
  if (const auto sc = r.optional_numbers("variation_scales", 2, kPositive))
    g.shading.scales = {(*sc)[0], (*sc)[1]};
  for (TableReader& rule : r.tables("rules")) g.shading.rules.push_back(read_rule(rule));
  read_textures(r, base_dir, g);
  g.shading.texture_size = r.number("texture_size", kPositive, g.shading.texture_size);
  g.detail = r.boolean("detail", g.detail);
  read_per_material(r, "detail_amplitude", "metres 0-50, or a table of material = metres",
                    "0.3 (rock 1.0, grass 0.2, road, water and surroundings 0)", Range{0.0, 50.0},
                    g.detail_amplitude);
  read_per_material(r, "detail_roughness", "a fraction 0-1, or a table of material = fraction",
                    "0.5 (rock 0.6)", kUnit, g.detail_roughness);
  r.finish();
  return g;
}

// [[objects.material]] tables of one object: overrides of its mesh's materials by name.
std::vector<ObjectMaterialOverride> read_object_materials(TableReader& r) {
  std::vector<ObjectMaterialOverride> out;
  std::set<std::string> names;
  for (TableReader& m : r.tables("material")) {
    ObjectMaterialOverride o;
    o.location = m.location(nullptr);
    o.material = m.string("name");
    if (!names.insert(o.material).second)
      m.fail("name", "material '" + o.material + "' is overridden twice");
    if (const auto a = m.optional_numbers("albedo", 3, kUnit))
      o.albedo = Vec3f{static_cast<float>((*a)[0]), static_cast<float>((*a)[1]),
                       static_cast<float>((*a)[2])};
    if (const auto v = m.optional_number("roughness", kUnit)) o.roughness = static_cast<float>(*v);
    if (const auto v = m.optional_number("metallic", kUnit)) o.metallic = static_cast<float>(*v);
    m.finish();
    out.push_back(std::move(o));
  }
  return out;
}

// `position`: [x, y] (standing on the ground) or [x, y, z], terrain coordinates.
void read_object_position(TableReader& r, ObjectSettings& o) {
  const toml::node* n = r.value("position", "[x, y] or [x, y, z], terrain coordinates", "");
  if (n == nullptr) r.fail("position", "required key is missing: give [x, y] or [x, y, z]");
  o.position_location = r.location(n);
  const toml::array* a = n->as_array();
  if (a == nullptr || (a->size() != 2 && a->size() != 3))
    r.fail_at(*n, "position", "expected [x, y] or [x, y, z] (terrain coordinates, metres)");
  std::array<double, 3> v{};
  for (std::size_t k = 0; k < a->size(); ++k) {
    const std::optional<double> x = a->get(k)->value<double>();
    if (!x || !std::isfinite(*x))
      r.fail_at(*a->get(k), "position", "expected a number, got " + params::type_name(*a->get(k)));
    v[k] = *x;
  }
  o.x = v[0];
  o.y = v[1];
  if (a->size() == 3) o.z = v[2];
}

// [[objects]]: meshes placed on the terrain; names unique, files present.
std::vector<ObjectSettings> read_objects(const toml::table& root, const std::string& file,
                                         const std::string& base_dir) {
  std::vector<ObjectSettings> out;
  const toml::array* a = tables(root, "objects", file);
  if (a == nullptr) return out;
  std::set<std::string> names;
  for (std::size_t i = 0; i < a->size(); ++i) {
    const toml::table& t = *a->get(i)->as_table();
    TableReader r(t, "objects[" + std::to_string(i) + "]", file);
    ObjectSettings o;
    o.path = "objects[" + std::to_string(i) + "]";
    o.location = r.location(nullptr);
    o.name = r.string("name");
    if (o.name.empty()) r.fail("name", "expected a name (a non-empty string)");
    if (!names.insert(o.name).second)
      r.fail("name", "the name '" + o.name + "' is used by another object (names must be unique)");
    o.file = resolve(base_dir, r.string("file"));
    o.file_location = r.location(t.get("file"));
    if (!std::filesystem::is_regular_file(o.file))
      r.fail("file", "file not found: " + o.file + " (expected a mesh: OBJ, PLY, glTF or GLB)");
    read_object_position(r, o);
    o.heading_deg = r.number("heading", Range{-360.0, 360.0}, o.heading_deg);
    o.scale = r.number("scale", Range{0.0, 1000.0, true}, o.scale);
    o.unit_scale = r.number("unit_scale", Range{0.0, 1e6, true}, o.unit_scale);
    o.z_up = r.choice("up_axis", {"y", "z"}, "y") == "z";
    o.align_to_ground = r.boolean("align_to_ground", o.align_to_ground);
    o.clear_radius = r.optional_number("clear_radius", Range{0.0, 10000.0});
    o.materials = read_object_materials(r);
    r.finish();
    out.push_back(std::move(o));
  }
  return out;
}

// [[bands]]: sensor bands, each a name and a response (a file, or a box).
std::vector<BandSettings> read_bands(const toml::table& root, const std::string& file,
                                     const std::string& base_dir) {
  std::vector<BandSettings> out;
  const toml::array* a = tables(root, "bands", file);
  if (a == nullptr) return out;
  std::set<std::string> names;
  for (std::size_t i = 0; i < a->size(); ++i) {
    TableReader r(*a->get(i)->as_table(), "bands[" + std::to_string(i) + "]", file);
    if (i >= static_cast<std::size_t>(kMaxSensorBands))
      r.fail("name", "at most " + std::to_string(kMaxSensorBands) + " bands per image set");
    BandSettings b;
    b.name = detail::read_layer_name(r, "band.", names, "is used by another band");
    b.response = detail::read_response(r, base_dir, b.description);
    r.finish();
    out.push_back(std::move(b));
  }
  return out;
}

void refuse_unknown_tables(const toml::table& root, const std::string& file) {
  static const std::set<std::string, std::less<>> kKnown{
      "terrain", "sun",  "views", "render", "featuremaps", "species", "grass",
      "ground",  "wind", "sky",   "haze",   "objects",     "bands",   "sensor"};
  for (auto&& [key, value] : root) {
    if (kKnown.count(key.str()) != 0) continue;
    const auto& b = key.source().begin;
    throw InputError(
        file + ":" + std::to_string(b.line) + ":" + std::to_string(b.column) +
        ": unknown table or key '" + std::string(key.str()) + "'" +
        params::did_you_mean(key.str(), std::vector<std::string>(kKnown.begin(), kKnown.end())) +
        " (expected terrain, featuremaps, species, grass, ground, wind, sun, sky, "
        "haze, views, render, objects, bands, sensor)");
  }
}

}  // namespace

void check_image_size(int width, int height, const std::string& where) {
  const std::string prefix = where.empty() ? "" : where + ": ";
  if (width < 1 || height < 1 || width > kMaxImageSide || height > kMaxImageSide) {
    throw InputError(prefix + "image size " + std::to_string(width) + " x " +
                     std::to_string(height) + ": each side must be from 1 to " +
                     std::to_string(kMaxImageSide));
  }
  if (double(width) * double(height) > kMaxImagePixels) {
    throw InputError(prefix + "image of " + std::to_string(width) + " x " + std::to_string(height) +
                     " pixels exceeds the limit of 100 million pixels");
  }
}

Scenario parse_scenario(std::string_view text, const std::string& source,
                        const std::string& base_dir, const std::vector<std::string>& sets) {
  toml::table root;
  try {
    root = toml::parse(text, source);
  } catch (const toml::parse_error& e) {
    throw InputError(params::parse_error_message(e, source));
  }
  if (root.contains("core"))
    throw InputError(source +
                     ": this is a species file (it names a tree core), not a scenario; a "
                     "scenario has [terrain], [sun] and [[views]] (landsim tree takes species "
                     "files)");
  detail::apply_overrides(root, sets);
  refuse_unknown_tables(root, source);
  Scenario s;
  s.source = source;
  std::uint64_t hash = fnv1a(text);  // over the text and the overrides
  for (const std::string& set : sets) hash = fnv1a("\n--set " + set, hash);
  s.text_hash = fmt::format("{:016x}", hash);
  s.terrain = read_terrain(sub_table(root, "terrain", source, true), source, base_dir);
  s.sun = read_sun(sub_table(root, "sun", source, true), source);
  s.featuremaps = read_featuremaps(root, source, base_dir);
  s.species = read_species(root, source, base_dir);
  s.grass = read_grass(root, source);
  s.ground = read_ground(root, source, base_dir);
  // Where the i-th [[grass]] or [[species]] table stands, for the messages below.
  const auto where = [&](std::string_view key, std::size_t i) {
    const toml::array* a = root.get(key) != nullptr ? root.get(key)->as_array() : nullptr;
    const toml::node* first = a != nullptr && a->size() > i ? a->get(i) : root.get(key);
    const auto& b = first->source().begin;
    return source + ":" + std::to_string(b.line) + ":" + std::to_string(b.column);
  };
  // Vegetation grows where a feature map or its own cover says; with neither it would grow
  // nowhere.
  const bool maps =
      s.featuremaps && (!s.featuremaps->vegetation.empty() || !s.featuremaps->classes.empty());
  for (std::size_t i = 0; i < s.grass.size() && !maps; ++i)
    if (!s.grass[i].cover)
      throw InputError(where("grass", i) + ": [[grass]] type " + std::to_string(s.grass[i].type) +
                       " grows nowhere: give it a cover (\"everywhere\", a fraction, a "
                       "rectangle or a polygon) or add [featuremaps] vegetation or classes");
  for (std::size_t i = 0; i < s.species.size() && !maps; ++i)
    if (!s.species[i].cover)
      throw InputError(where("species", i) + ": [[species]] bit " +
                       std::to_string(s.species[i].bit) +
                       " grows nowhere: give it a cover (\"everywhere\", a fraction, a "
                       "rectangle or a polygon) or add [featuremaps] vegetation or classes");
  // Bands before the sensor, the sensor before the views: the channels share the bands'
  // layers, and each view may override the sensor.
  s.bands = read_bands(root, source, base_dir);
  s.sensor = detail::read_sensor(root, source, base_dir, s.bands.size());
  s.views = read_views(root, source, s.sensor);
  s.render = read_render(sub_table(root, "render", source, false), source);
  s.wind = read_wind(sub_table(root, "wind", source, false), source);
  s.sky = read_sky(sub_table(root, "sky", source, false), source);
  s.haze = read_haze(root, source);
  s.objects = read_objects(root, source, base_dir);
  return s;
}

bool has_cover(const Scenario& s) {
  return std::any_of(s.species.begin(), s.species.end(), [](const auto& k) { return k.cover; }) ||
         std::any_of(s.grass.begin(), s.grass.end(), [](const auto& g) { return g.cover; });
}

SensorSettings load_sensor(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in || std::filesystem::is_directory(file))
    throw InputError(file.string() + ": cannot open sensor file");
  std::ostringstream text;
  text << in.rdbuf();
  toml::table root;
  try {
    root = toml::parse(text.str(), file.string());
  } catch (const toml::parse_error& e) {
    throw InputError(params::parse_error_message(e, file.string()));
  }
  for (auto&& [key, value] : root)
    if (key.str() != "sensor") {
      const auto& b = key.source().begin;
      throw InputError(
          fmt::format("{}:{}:{}: unknown table or key '{}' (a sensor file holds "
                      "[sensor] alone)",
                      file.string(), b.line, b.column, key.str()));
    }
  std::optional<SensorSettings> s =
      detail::read_sensor(root, file.string(), file.parent_path().string(), 0);
  if (!s) throw InputError(file.string() + ": no [sensor] table");
  return *s;
}

ScenarioText read_scenario_text(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in || std::filesystem::is_directory(file)) {
    throw InputError(file.string() + ": cannot open scenario file");
  }
  std::ostringstream text;
  text << in.rdbuf();
  return {text.str(), file.string(), file.parent_path().string()};
}

Scenario parse_scenario(const ScenarioText& t, const std::vector<std::string>& sets) {
  return parse_scenario(t.text, t.source, t.base_dir, sets);
}

std::string scenario_toml(const ScenarioText& t, const std::vector<std::string>& sets) {
  toml::table root;
  try {
    root = toml::parse(t.text, t.source);
  } catch (const toml::parse_error& e) {
    throw InputError(params::parse_error_message(e, t.source));
  }
  detail::apply_overrides(root, sets);
  std::ostringstream out;
  out << root << "\n";
  return out.str();
}

Scenario load_scenario(const std::filesystem::path& file, const std::vector<std::string>& sets) {
  return parse_scenario(read_scenario_text(file), sets);
}

}  // namespace landsim::scenes
