#include "scenes/image_set/sensor_output.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/atomic_file.h"
#include "core/input_error.h"
#include "renderer/output/image_io.h"
#include "renderer/output/image_output.h"
#include "renderer/sensor/digitiser.h"
#include "renderer/sensor/optics.h"
#include "renderer/sensor/vignetting.h"
#include "scenes/image_set/detail/geo_rasters.h"
#include "scenes/image_set/image_set.h"
#include "scenes/scenario/sensor_bands.h"
#include "terrain/raster_io.h"

namespace landsim::scenes {
namespace {

// The MTF table of the manifest: every 0.05 cycles per pixel up to 1.
nlohmann::json mtf_table(double wavelength_nm, const renderer::SensorModel& m) {
  nlohmann::json rows = nlohmann::json::array();
  for (int i = 0; i <= 20; ++i) {
    const double f = 0.05 * i;
    rows.push_back({f, renderer::system_mtf(f, wavelength_nm, m)});
  }
  return rows;
}

// The photon plane of each channel, through the optics (the lens's point spread, then its
// vignetting: both before the exposure is chosen, as a camera meters what reaches it).
std::vector<std::vector<float>> optical_planes(const renderer::Film& film,
                                               const renderer::SensorModel& m,
                                               const renderer::ImageField& field,
                                               const std::string& stem) {
  const std::vector<double> fall_off =
      renderer::vignetting_factors(film.width(), film.height(), field, m.vignetting);
  std::vector<std::vector<float>> planes;
  for (const renderer::SensorChannel& c : m.channels) {
    const auto& names = film.band_names();
    const auto it = std::find(names.begin(), names.end(), photon_layer(c.name));
    if (it == names.end())
      throw InputError(
          fmt::format("{}: no layer {} for the sensor's channel {} (render the set "
                      "with this channel in [sensor])",
                      stem, photon_layer(c.name), c.name));
    std::vector<float> plane = film.band_data(static_cast<int>(it - names.begin()));
    renderer::apply_optics(plane, film.width(), film.height(), c.wavelength_nm, m);
    renderer::apply_vignetting(plane, fall_off);
    planes.push_back(std::move(plane));
  }
  return planes;
}

void write_png(const std::vector<std::vector<std::uint16_t>>& dn, int w, int h,
               const std::filesystem::path& path) {
  renderer::FloatImage image{w, h, static_cast<int>(dn.size()), {}};
  image.pixels.resize(static_cast<std::size_t>(w) * h * dn.size());
  for (std::size_t i = 0; i < static_cast<std::size_t>(w) * h; ++i)
    for (std::size_t c = 0; c < dn.size(); ++c)
      image.pixels[i * dn.size() + c] = static_cast<float>(dn[c][i]) / 255.0f;
  AtomicFile out(path);
  std::string error, warning;
  if (!renderer::image_io().write_png(out.temp_path().string(), image, false, {}, error, warning))
    throw std::runtime_error("writing " + path.string() + " failed: " + error);
  out.commit();
}

void write_tiff(const std::vector<std::vector<std::uint16_t>>& dn, int w, int h,
                const renderer::SensorModel& m, const SensorPlacement& placement,
                const std::string& model, const std::filesystem::path& dir,
                const std::string& name) {
  terrain::OutputRaster r;
  r.driver = "GTiff";
  r.cols = w;
  r.rows = h;
  r.type = terrain::CellType::uint16;
  for (std::size_t c = 0; c < dn.size(); ++c)
    r.bands.push_back({m.channels[c].name, dn[c].data(), m.channels[c].wavelength_nm});
  r.geotransform = placement.geotransform;
  r.crs_wkt = placement.crs_wkt;
  r.metadata = {{"landsim_sensor", model}, {"unit", "digital numbers"}};
  detail::write_raster_file(r, dir, name);
}

}  // namespace

std::string sensor_image_name(const std::string& stem, const renderer::SensorModel& m) {
  return stem + (m.adc_bits <= 8 ? "_dn.png" : "_dn.tif");
}

nlohmann::json sensor_json(const renderer::SensorModel& m) {
  nlohmann::json channels = nlohmann::json::array();
  for (const renderer::SensorChannel& c : m.channels)
    channels.push_back({{"name", c.name},
                        {"layer", photon_layer(c.name)},
                        {"definition", c.definition},
                        {"wavelength_nm", c.wavelength_nm}});
  nlohmann::json j = {{"channels", channels},
                      {"quantum_efficiency", m.quantum_efficiency},
                      {"pixel_pitch_um", m.pixel_pitch_um},
                      {"f_number", m.f_number},
                      {"transmittance", m.transmittance},
                      {"gain_e_per_dn", renderer::gain_e_per_dn(m)},
                      {"full_well_e", m.full_well_e},
                      {"read_noise_e", m.read_noise_e},
                      {"dark_current_e_per_s", m.dark_current_e_per_s},
                      {"adc_bits", m.adc_bits},
                      {"black_level_dn", m.black_level_dn},
                      {"blur_sigma_um", m.blur_sigma_um},
                      {"noise_seed", m.noise_seed},
                      {"pixel_etendue_m2_sr", renderer::pixel_etendue(m)},
                      {"natural_vignetting", m.vignetting.natural},
                      {"lens_vignetting", m.vignetting.lens}};
  j["exposure_time_s"] =
      m.exposure_time_s ? nlohmann::json(*m.exposure_time_s) : nlohmann::json("auto");
  if (m.iso) j["iso"] = *m.iso;
  return j;
}

renderer::SensorModel sensor_from_json(const nlohmann::json& j, const std::string& source) {
  try {
    renderer::SensorModel m;
    for (const nlohmann::json& c : j.at("channels"))
      m.channels.push_back({c.at("name").get<std::string>(), c.at("definition").get<std::string>(),
                            c.at("wavelength_nm").get<double>()});
    m.quantum_efficiency = j.at("quantum_efficiency").get<double>();
    m.pixel_pitch_um = j.at("pixel_pitch_um").get<double>();
    m.f_number = j.at("f_number").get<double>();
    m.transmittance = j.at("transmittance").get<double>();
    m.gain_e_per_dn = j.at("gain_e_per_dn").get<double>();
    m.full_well_e = j.at("full_well_e").get<double>();
    m.read_noise_e = j.at("read_noise_e").get<double>();
    m.dark_current_e_per_s = j.at("dark_current_e_per_s").get<double>();
    m.adc_bits = j.at("adc_bits").get<int>();
    m.black_level_dn = j.at("black_level_dn").get<int>();
    m.blur_sigma_um = j.at("blur_sigma_um").get<double>();
    m.noise_seed = j.at("noise_seed").get<std::uint64_t>();
    const nlohmann::json& t = j.at("exposure_time_s");
    if (t.is_number()) m.exposure_time_s = t.get<double>();
    if (j.contains("iso")) m.iso = j.at("iso").get<double>();
    // Sets rendered before vignetting was modelled have neither key: no vignetting.
    m.vignetting.natural = j.value("natural_vignetting", false);
    if (j.contains("lens_vignetting"))
      m.vignetting.lens = j.at("lens_vignetting").get<std::array<double, 3>>();
    if (m.adc_bits < 8 || m.adc_bits > 16 || m.channels.empty() || !(m.f_number > 0.0) ||
        !(m.pixel_pitch_um > 0.0) || !(m.gain_e_per_dn > 0.0))
      throw std::out_of_range("values out of range");
    return m;
  } catch (const std::exception& e) {
    throw InputError(source + ": its sensor model is not one landsim wrote (" + e.what() + ")");
  }
}

renderer::ImageField image_field(const nlohmann::json& camera, const std::string& source) {
  try {
    const int w = camera.at("width").get<int>(), h = camera.at("height").get<int>();
    renderer::ImageField f;
    const std::string projection = camera.at("projection").get<std::string>();
    const auto known = renderer::projection_from_name(projection);
    if (!known) throw std::out_of_range("projection \"" + projection + "\"");
    f.projection = *known;
    // Without K (orthographic, spherical) the lens polynomial centres on the image.
    f.cx = 0.5 * w;
    f.cy = 0.5 * h;
    double sensor_w = w, sensor_h = h;
    if (camera.contains("K")) {
      const nlohmann::json& k = camera.at("K");
      f.fx = k.at(0).at(0).get<double>();
      f.fy = k.at(1).at(1).get<double>();
      // K's pixel centres sit on integers; landsim's on halves.
      f.cx = k.at(0).at(2).get<double>() + 0.5;
      f.cy = k.at(1).at(2).get<double>() + 0.5;
    }
    if (camera.contains("sensor_region")) {
      const nlohmann::json& pixels = camera.at("sensor_region").at("sensor_pixels");
      sensor_w = pixels.at(0).get<double>();
      sensor_h = pixels.at(1).get<double>();
    }
    f.half_diagonal_px = 0.5 * std::hypot(sensor_w, sensor_h);
    if (camera.contains("distortion")) {
      const nlohmann::json& d = camera.at("distortion");
      f.distortion = {d.at("k1").get<double>(), d.at("k2").get<double>(), d.at("k3").get<double>(),
                      d.at("p1").get<double>(), d.at("p2").get<double>()};
    }
    return f;
  } catch (const std::exception& e) {
    throw InputError(source + ": its camera model is not one landsim wrote (" + e.what() + ")");
  }
}

nlohmann::json write_sensor_image(const renderer::Film& film, const renderer::SensorModel& m,
                                  const std::filesystem::path& dir, const std::string& stem,
                                  const SensorPlacement& placement) {
  const int w = film.width(), h = film.height();
  const std::vector<std::vector<float>> planes = optical_planes(film, m, placement.field, stem);
  std::vector<const std::vector<float>*> pointers;
  for (const auto& p : planes) pointers.push_back(&p);
  const double exposure =
      m.exposure_time_s ? *m.exposure_time_s : renderer::auto_exposure_time(pointers, m);
  std::vector<std::vector<std::uint16_t>> dn;
  for (std::size_t c = 0; c < planes.size(); ++c)
    dn.push_back(renderer::digitise(planes[c], w, h, exposure, m, stem, static_cast<int>(c)));
  nlohmann::json entry = sensor_json(m);
  entry["exposure_time_used_s"] = exposure;
  for (std::size_t c = 0; c < m.channels.size(); ++c) {
    nlohmann::json& ch = entry["channels"][c];
    ch["mtf50_cycles_per_pixel"] = renderer::mtf50(m.channels[c].wavelength_nm, m);
    ch["mtf"] = mtf_table(m.channels[c].wavelength_nm, m);
  }
  if (placement.geotransform) entry["geotransform"] = *placement.geotransform;
  if (!placement.crs_wkt.empty()) entry["crs_wkt"] = placement.crs_wkt;
  const bool png = m.adc_bits <= 8;
  const std::string file = sensor_image_name(stem, m);
  entry["path"] = file;
  if (png)
    write_png(dn, w, h, dir / file);
  else
    write_tiff(dn, w, h, m, placement, entry.dump(), dir, stem + "_dn");
  return entry;
}

namespace {

// The sensor an image was rendered with and where its digital numbers sit (its EXR's "sensor"
// attribute: the entry write_sensor_image made).
struct RenderedSensor {
  renderer::SensorModel model;
  SensorPlacement placement;
};

// The EXR's "camera" attribute (camera_json of its view).
nlohmann::json camera_attribute(const renderer::ImageMetadata& meta, const std::string& source) {
  for (const auto& [key, value] : meta) {
    if (key != "camera") continue;
    const nlohmann::json j = nlohmann::json::parse(value, nullptr, false);
    if (j.is_discarded() || !j.is_object()) break;
    return j;
  }
  throw InputError(source + ": it holds no camera model (landsim/camera) for the sensor's field");
}

std::optional<RenderedSensor> rendered_sensor(const renderer::ImageMetadata& meta,
                                              const std::string& source) {
  for (const auto& [key, value] : meta) {
    if (key != "sensor") continue;
    const nlohmann::json j = nlohmann::json::parse(value, nullptr, false);
    if (j.is_discarded() || !j.is_object())
      throw InputError(source + ": its sensor attribute is not a JSON object");
    RenderedSensor out{sensor_from_json(j, source), {}};
    out.placement.field = image_field(camera_attribute(meta, source), source);
    try {
      if (j.contains("geotransform"))
        out.placement.geotransform = j["geotransform"].get<std::array<double, 6>>();
      out.placement.crs_wkt = j.value("crs_wkt", std::string());
    } catch (const std::exception& e) {
      throw InputError(source + ": its sensor attribute's placement is not landsim's (" + e.what() +
                       ")");
    }
    return out;
  }
  return std::nullopt;
}

// Another sensor's channels must be ones the image rendered, with the same responses.
void check_channels(const renderer::SensorModel& wanted, const renderer::SensorModel& rendered,
                    const std::string& source) {
  for (const renderer::SensorChannel& c : wanted.channels) {
    const auto it = std::find_if(rendered.channels.begin(), rendered.channels.end(),
                                 [&](const auto& r) { return r.name == c.name; });
    if (it == rendered.channels.end()) {
      std::string names;
      for (const auto& r : rendered.channels) names += (names.empty() ? "" : ", ") + r.name;
      throw InputError(
          fmt::format("{}: channel {} was not rendered (its channels: {}); render "
                      "the set again with it in [sensor]",
                      source, c.name, names));
    }
    if (it->definition != c.definition)
      throw InputError(
          fmt::format("{}: channel {} was rendered as \"{}\", the sensor defines "
                      "\"{}\": render the set again with the new response",
                      source, c.name, it->definition, c.definition));
  }
}

// A file of the set into `to`: a hard link where the file system allows, else a copy.
void link_or_copy(const std::filesystem::path& from, const std::filesystem::path& to) {
  std::error_code error;
  std::filesystem::remove(to, error);
  std::filesystem::create_hard_link(from, to, error);
  if (error)
    std::filesystem::copy_file(from, to, std::filesystem::copy_options::overwrite_existing);
}

}  // namespace

std::vector<std::filesystem::path> sense_image_set(const std::filesystem::path& dir,
                                                   const SenseOptions& options) {
  nlohmann::json manifest = read_manifest(dir);
  const std::filesystem::path out = options.out.empty() ? dir : options.out;
  if (!options.out.empty()) {
    if (std::filesystem::exists(out) && std::filesystem::equivalent(out, dir))
      throw InputError(out.string() +
                       ": the sensed set would overwrite the set: give another "
                       "folder, or --in-place");
    std::filesystem::create_directories(out);
  }
  const std::filesystem::path manifest_path = out / "manifest.json";
  std::vector<std::filesystem::path> written;
  for (nlohmann::json& entry : manifest["images"]) {
    if (!entry.contains("path") || !entry["path"].is_string())
      throw InputError(manifest_path.string() + ": an image without a \"path\"");
    const std::string exr_name = entry["path"].get<std::string>();
    const std::filesystem::path exr = dir / exr_name;
    renderer::ImageMetadata meta;
    renderer::Film film(1, 1);
    try {
      film = renderer::read_exr(exr, &meta);
    } catch (const std::exception& e) {
      throw InputError(exr.string() + ": cannot read the image: " + e.what());
    }
    // Only a set rendered with a sensor holds the photon layers any sensor reads.
    const std::optional<RenderedSensor> rendered = rendered_sensor(meta, exr.string());
    if (!rendered)
      throw InputError(exr.string() +
                       ": rendered without [sensor] (no photon layers): render "
                       "the set with a [sensor] table");
    renderer::SensorModel m = options.sensor ? *options.sensor : rendered->model;
    if (options.sensor) check_channels(m, rendered->model, exr.string());
    if (options.noise_seed) m.noise_seed = *options.noise_seed;
    if (options.exposure_time_s) m.exposure_time_s = *options.exposure_time_s;
    const std::string stem = std::filesystem::path(exr_name).stem().string();
    if (out != dir) {
      link_or_copy(exr, out / exr_name);
      if (entry.contains("preview") && entry["preview"].is_string())
        link_or_copy(dir / entry["preview"].get<std::string>(),
                     out / entry["preview"].get<std::string>());
    }
    entry["sensor"] = write_sensor_image(film, m, out, stem, rendered->placement);
    written.push_back(out / entry["sensor"]["path"].get<std::string>());
  }
  write_file_atomically(manifest_path, manifest.dump(2) + "\n");
  return written;
}

}  // namespace landsim::scenes
