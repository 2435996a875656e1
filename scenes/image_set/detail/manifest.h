#pragma once
// Private to scenes/image_set/: what the set says of each image: the manifest (manifest.json)
// and the EXR header's metadata (what made the image, its camera, its objects' truth, its
// irradiance), and the entry of an image already written, read back from its EXR (resume).
#include <nlohmann/json_fwd.hpp>

#include <filesystem>
#include <string>
#include <vector>

#include "renderer/output/image_output.h"
#include "renderer/output/object_truth.h"
#include "renderer/output/reflectance.h"
#include "renderer/scene.h"
#include "scenes/scenario/scenario.h"

namespace landsim::scenes::detail {

// The whole camera model (docs/CAMERAS.md), positions and axes in terrain coordinates: in the
// manifest and, as JSON text, the EXR's "camera" attribute.
nlohmann::json camera_json(const renderer::View& v, const Vec3& origin);

// The EXR header's description of the image: what made it.
// `camera`: camera_json of the view.
renderer::ImageMetadata metadata(const Scenario& s, const renderer::View& v,
                                 const renderer::Scene& scene, const nlohmann::json& camera);

// `complete`: false when a later image failed; the manifest then lists the images finished
// before it, so that a set is never left without one (resume continues it).
void write_manifest(const std::filesystem::path& path, const Scenario& s,
                    const nlohmann::json& images, bool complete = true);

// `camera`: camera_json of the image's placed view.
nlohmann::json manifest_entry(const ViewSettings& vs, const std::string& stem, std::size_t f,
                              double time, nlohmann::json camera);

// The manifest's truth about each object in an image (docs/OBJECTS.md "Truth").
// A randomised image's record (docs/SCENARIO.md [randomise]): its index and its draws.
nlohmann::json randomised_json(std::size_t image, const std::vector<std::string>& set);

// The image's resolved settings (docs/SCENARIO.md "Image sets"): the scenario's hash, sun
// (with the irradiance used), sky, haze, wind and render settings, as the image was made.
nlohmann::json settings_json(const Scenario& s, const renderer::Scene& scene);

nlohmann::json objects_json(const std::vector<renderer::ObjectTruth>& truth, const Vec3& origin);

// A JSON attribute (objects, camera) of an image already written; null when it has none.
nlohmann::json saved_json(const std::filesystem::path& exr, const std::string& attribute);

// The image's irradiance as the manifest and the EXR give it (docs/SENSOR.md).
nlohmann::json irradiance_json(const renderer::ImageIrradiance& e, const renderer::Scene& scene);

// How noisy the image is, from its own samples (renderer/output/image_noise.h); null when it
// cannot say (1 sample a pixel, a black frame). Under the Sobol sampler an upper bound (its
// stratified samples spread more than their mean errs), which `upper_bound` says.
nlohmann::json noise_json(const renderer::Film& film, SampleSequence sampler);

// The manifest entry of an image already written, from what its EXR keeps.
nlohmann::json saved_entry(const Scenario& s, std::size_t view, const std::string& stem,
                           std::size_t frame, const std::filesystem::path& exr);

}  // namespace landsim::scenes::detail
