#pragma once
// A view's sensor image (docs/SENSOR.md): the film's photon-radiance layers through the
// optics, exposed, noised and digitised into <stem>_dn.tif (16 bits, through GDAL, the sensor
// model in its metadata) or, for an ADC of 8 bits, <stem>_dn.png; and the sensor model as
// JSON for the manifest and the EXR. `landsim render` calls it for every view of a scenario
// with [sensor]; `landsim sense` calls it again on a stored image set.
#include <array>
#include <filesystem>
#include <nlohmann/json_fwd.hpp>
#include <optional>
#include <string>

#include "renderer/output/film.h"
#include "renderer/sensor/sensor_model.h"

namespace landsim::scenes {

// The file name write_sensor_image gives an image: <stem>_dn.tif, or .png for 8 bits.
std::string sensor_image_name(const std::string& stem, const renderer::SensorModel& m);

// Where a sensor image sits: in the terrain's CRS (map views only), and behind which lens
// (the field its vignetting needs).
struct SensorPlacement {
  std::optional<std::array<double, 6>> geotransform;
  std::string crs_wkt;
  renderer::ImageField field;
};

// The field of a view's camera model as camera_json describes it (the manifest's and the
// EXR's "camera"): its projection, K, distortion and the whole sensor's size. Throws
// InputError naming `source` when the description is not landsim's.
renderer::ImageField image_field(const nlohmann::json& camera, const std::string& source);

// Writes dir/<stem>_dn.tif (or .png) from `film` (which holds the model's photon layers),
// vignetted over placement.field when the model asks, and returns the manifest's "sensor" entry:
// the model, the exposure used, each channel's MTF. Throws InputError naming the image when a
// channel's layer is missing.
nlohmann::json write_sensor_image(const renderer::Film& film, const renderer::SensorModel& m,
                                  const std::filesystem::path& dir, const std::string& stem,
                                  const SensorPlacement& placement = {});

// `landsim sense`: what changes from the sensor each image was rendered with.
struct SenseOptions {
  std::optional<renderer::SensorModel> sensor;  // another sensor (its channels rendered)
  std::optional<std::uint64_t> noise_seed;
  std::optional<double> exposure_time_s;
  // Where the sensed set goes: empty rewrites the set in place; else a new folder holding the
  // set's EXRs and previews (hard links where the file system allows, else copies), the new
  // digital numbers and its own manifest, the set itself untouched.
  std::filesystem::path out;
};

// Applies a sensor again to every image of the set in `dir` (its manifest.json): the digital
// numbers written (into options.out, or over the set's), the manifest's "sensor" entries
// updated (the EXRs keep the sensor they
// were rendered with). Returns the files written. Throws InputError naming the set, image or
// channel when the set cannot take the sensor (no manifest, a channel not rendered, or
// rendered with another response).
std::vector<std::filesystem::path> sense_image_set(const std::filesystem::path& dir,
                                                   const SenseOptions& options);

// The model as write_sensor_image's entry holds it, and back (sense on a stored set);
// from_json throws InputError naming `source` when the entry is not one of ours.
nlohmann::json sensor_json(const renderer::SensorModel& m);
renderer::SensorModel sensor_from_json(const nlohmann::json& j, const std::string& source);

}  // namespace landsim::scenes
