#include "scenes/scenario/detail/sensor_reader.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <regex>
#include <set>

#include "core/input_error.h"
#include "renderer/spectra/channel_presets.h"
#include "scenes/scenario/detail/relative_path.h"
#include "scenes/scenario/detail/toml_tables.h"
#include "scenes/scenario/sensor_bands.h"
#include "terrain/raster_files.h"

namespace landsim::scenes::detail {
namespace {

using params::Range;
using params::TableReader;

// "auto" (empty) or seconds.
std::optional<double> read_exposure_time(TableReader& r, std::optional<double> fallback) {
  const std::string expected = "\"auto\" or seconds, more than 0 and at most 3600";
  const toml::node* n = r.value("exposure_time", expected, "\"auto\"");
  if (n == nullptr) return fallback;
  if (const auto* s = n->as_string()) {
    if (s->get() == "auto") return std::nullopt;
    r.fail_at(*n, "exposure_time", "expected " + expected + ", got \"" + s->get() + "\"");
  }
  const std::optional<double> t = n->is_number() ? n->value<double>() : std::nullopt;
  if (!t || !(*t > 0.0 && *t <= 3600.0)) r.fail_at(*n, "exposure_time", "expected " + expected);
  return *t;
}

// natural_vignetting (the ideal lens's fall-off) and lens_vignetting (lensfun's "pa"
// polynomial, k1 k2 k3): a polynomial that reaches zero inside the frame is refused.
void read_vignetting(TableReader& r, renderer::VignettingModel& v) {
  v.natural = r.boolean("natural_vignetting", v.natural);
  const std::vector<double> k = r.numbers("lens_vignetting", 3, Range{-100.0, 100.0},
                                          std::vector<double>(v.lens.begin(), v.lens.end()));
  std::copy(k.begin(), k.end(), v.lens.begin());
  const double least = renderer::lens_polynomial_minimum(v.lens, 1.0);
  if (!(least > 0.0))
    r.fail("lens_vignetting",
           fmt::format("1 + k1 r^2 + k2 r^4 + k3 r^6 falls to {:.3g} inside the frame (r = 1 "
                       "at the sensor's corner); a lens's relative illumination stays above 0",
                       least));
}

// Every key but the channels, each defaulting to `m`'s value.
void read_model(TableReader& r, renderer::SensorModel& m) {
  m.quantum_efficiency =
      r.number("quantum_efficiency", Range{0.0, 1.0, true}, m.quantum_efficiency);
  m.pixel_pitch_um = r.number("pixel_pitch", Range{0.1, 1000.0}, m.pixel_pitch_um);
  m.exposure_time_s = read_exposure_time(r, m.exposure_time_s);
  m.f_number = r.number("f_number", Range{0.5, 1000.0}, m.f_number);
  m.transmittance = r.number("transmittance", Range{0.0, 1.0, true}, m.transmittance);
  m.adc_bits = static_cast<int>(r.integer("adc_bits", 8, 16, m.adc_bits));
  m.black_level_dn =
      static_cast<int>(r.integer("black_level", 0, renderer::max_dn(m) - 1, m.black_level_dn));
  if (r.has("gain") && r.has("iso")) r.fail("iso", "give gain (e-/DN) or iso, not both");
  if (r.has("gain")) m.iso.reset();
  m.gain_e_per_dn = r.number("gain", Range{1e-4, 1e6}, m.gain_e_per_dn);
  if (r.has("iso")) m.iso = r.number("iso", Range{1.0, 1e6});
  m.full_well_e = r.number("full_well", Range{1.0, 1e8}, m.full_well_e);
  m.read_noise_e = r.number("read_noise", Range{0.0, 1e4}, m.read_noise_e);
  m.dark_current_e_per_s = r.number("dark_current", Range{0.0, 1e8}, m.dark_current_e_per_s);
  m.blur_sigma_um = r.number("blur_sigma", Range{0.0, 1000.0}, m.blur_sigma_um);
  read_vignetting(r, m.vignetting);
  m.noise_seed = static_cast<std::uint64_t>(
      r.integer("noise_seed", 0, INT64_MAX, static_cast<std::int64_t>(m.noise_seed)));
  const std::size_t n = m.channels.size();
  if (m.adc_bits <= 8 && n != 1 && n != 3 && n != 4)
    r.fail("adc_bits", fmt::format("an ADC of 8 bits writes a PNG, which holds 1, 3 or 4 "
                                   "channels, not {}: use 9 to 16 bits (a 16-bit TIFF)",
                                   n));
}

// A channel named `name` with its response, described as what was rendered.
void add_channel(SensorSettings& s, std::string name, std::string definition,
                 std::vector<renderer::ResponsePoint> response) {
  s.model.channels.push_back(
      {std::move(name), std::move(definition), renderer::centroid_wavelength(response)});
  s.responses.push_back(std::move(response));
}

// `channels`: a preset's name, or an array of tables (name, and a response file or a box).
void read_channels(TableReader& r, const std::string& base_dir, SensorSettings& s) {
  const std::string expected = std::string("a preset (") + renderer::channel_preset_names() +
                               ") or an array of tables {name, response} or {name, centre, width}";
  const toml::node* n = r.value("channels", expected, "\"rgb\"");
  if (n == nullptr || n->is_string()) {
    const std::string preset = n != nullptr ? n->as_string()->get() : "rgb";
    const auto channels = renderer::channel_preset(preset);
    if (!channels) r.fail_at(*n, "channels", "expected " + expected + ", got \"" + preset + "\"");
    for (const renderer::PresetChannel& c : *channels)
      add_channel(s, c.name, "preset " + preset + " " + c.name, c.response);
    return;
  }
  if (!n->is_array()) r.fail_at(*n, "channels", "expected " + expected);
  std::set<std::string> names;
  for (TableReader& c : r.tables("channels")) {
    const std::string name = read_layer_name(c, "photons.", names, "is used twice");
    std::string description;
    std::vector<renderer::ResponsePoint> response = read_response(c, base_dir, description);
    c.finish();
    add_channel(s, name, description, std::move(response));
  }
  if (s.model.channels.empty()) r.fail_at(*n, "channels", "expected at least one channel");
}

}  // namespace

std::string read_layer_name(TableReader& r, const std::string& layer, std::set<std::string>& taken,
                            const std::string& duplicate) {
  static const std::regex kName("[A-Za-z0-9_-]{1,32}");
  std::string name = r.string("name");
  if (!std::regex_match(name, kName))
    r.fail("name", "expected 1-32 letters, digits, '_' or '-' (it names the EXR layer " + layer +
                       name + ")");
  if (!taken.insert(name).second) r.fail("name", "the name '" + name + "' " + duplicate);
  return name;
}

std::vector<renderer::ResponsePoint> read_response(TableReader& r, const std::string& base_dir,
                                                   std::string& description) {
  const bool has_file = r.has("response");
  const bool has_box = r.has("centre") || r.has("width");
  if (has_file == has_box)
    r.fail(has_file ? "centre" : "response",
           "give either response (a CSV file of wavelength, response) or centre and width "
           "(a box, nm)");
  if (has_file) {
    const std::string path = resolve(base_dir, r.string("response"));
    const std::optional<std::string> text = terrain::read_text_file(path);
    if (!text)
      r.fail("response", "cannot read " + path + " (expected a CSV of wavelength, response)");
    description = "response " + path;
    return parse_band_response(*text, path);
  }
  const double centre =
      r.number("centre", Range{renderer::kFirstWavelength, renderer::kLastWavelength});
  const double width = r.number("width", Range{0.0, 640.0, true});
  if (centre - 0.5 * width < renderer::kFirstWavelength - 1e-9 ||
      centre + 0.5 * width > renderer::kLastWavelength + 1e-9)
    r.fail("width", fmt::format("the box {}-{} nm leaves 380-1020 nm, where landsim's spectra are",
                                centre - 0.5 * width, centre + 0.5 * width));
  description = fmt::format("box {}-{} nm", centre - 0.5 * width, centre + 0.5 * width);
  return renderer::box_response(centre, width);
}

std::optional<SensorSettings> read_sensor(const toml::table& root, const std::string& file,
                                          const std::string& base_dir, std::size_t bands) {
  const toml::node* n = root.get("sensor");
  if (n == nullptr) return std::nullopt;
  if (!n->is_table()) {
    const auto& b = n->source().begin;
    throw InputError(fmt::format("{}:{}:{}: sensor: expected a table", file, b.line, b.column));
  }
  TableReader r(*n->as_table(), "sensor", file);
  SensorSettings s;
  read_channels(r, base_dir, s);
  if (bands + s.model.channels.size() > static_cast<std::size_t>(kMaxSensorBands))
    r.fail("channels", fmt::format("{} channels and {} [[bands]]: at most {} layers in all",
                                   s.model.channels.size(), bands, kMaxSensorBands));
  read_model(r, s.model);
  for (auto&& [key, value] : *n->as_table()) s.keys.emplace_back(key.str());
  r.finish();
  return s;
}

namespace {

bool given(const TableReader& view_sensor, const SensorSettings& global, const char* key) {
  return view_sensor.has(key) ||
         std::find(global.keys.begin(), global.keys.end(), key) != global.keys.end();
}

// The view's lens decides what the sensor shares with it: its f-number (a thin lens) and,
// with a focal length, its pixel pitch.
void reconcile_with_lens(TableReader& r, const SensorSettings& global, const ViewSettings& v,
                         renderer::SensorModel& m) {
  const renderer::Lens& lens = v.lens;
  if (lens.aperture_radius > 0.0) {
    if (given(r, global, "f_number") && std::abs(m.f_number - lens.f_number) > 1e-9)
      r.fail("f_number", fmt::format("the sensor's f_number {} differs from the view's lens "
                                     "(f_number {}): give it once",
                                     m.f_number, lens.f_number));
    m.f_number = lens.f_number;
  }
  if (lens.projection != renderer::Projection::perspective || lens.focal_length_mm <= 0.0) return;
  if (std::abs(lens.fx_over_fy - 1.0) > 1e-9)
    r.fail("pixel_pitch", "the sensor model takes square pixels; the view's are not");
  const double pitch_um = 2.0 * lens.focal_length_mm *
                          std::tan(0.5 * v.fov_y_deg * std::numbers::pi / 180.0) / v.height * 1e3;
  if (given(r, global, "pixel_pitch") && std::abs(m.pixel_pitch_um / pitch_um - 1.0) > 1e-3)
    r.fail("pixel_pitch", fmt::format("the sensor's pixel_pitch {} um differs from the view's "
                                      "{:.4g} um (its focal_length and sensor): give it once",
                                      m.pixel_pitch_um, pitch_um));
  m.pixel_pitch_um = pitch_um;
}

}  // namespace

std::optional<renderer::SensorModel> read_view_sensor(TableReader& view,
                                                      const std::optional<SensorSettings>& global,
                                                      const ViewSettings& v) {
  if (!global) {
    if (view.has("sensor"))
      view.fail("sensor", "a view's sensor table overrides [sensor], which this scenario lacks");
    return std::nullopt;
  }
  TableReader r = view.table("sensor");
  if (r.has("channels"))
    r.fail("channels",
           "the channels are the scene's (every view renders them): set them in "
           "[sensor]");
  renderer::SensorModel m = global->model;
  read_model(r, m);
  reconcile_with_lens(r, *global, v, m);
  r.finish();
  return m;
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
    b.name = read_layer_name(r, "band.", names, "is used by another band");
    b.response = read_response(r, base_dir, b.description);
    r.finish();
    out.push_back(std::move(b));
  }
  return out;
}

}  // namespace landsim::scenes::detail
