#include "scenes/image_set/detail/manifest.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <filesystem>

#include "core/atomic_file.h"
#include "renderer/atmosphere/medium.h"
#include "renderer/camera.h"
#include "renderer/output/image_io.h"
#include "renderer/output/image_noise.h"
#include "renderer/output/image_output.h"
#include "renderer/spectra/colour_matching.h"
#include "scenes/image_set/detail/legend.h"

namespace landsim::scenes::detail {
namespace {

std::string vec_text(const Vec3& v) { return fmt::format("{} {} {}", v.x, v.y, v.z); }

nlohmann::json vec_json(const Vec3& v) { return nlohmann::json::array({v.x, v.y, v.z}); }

// The EXR's one-line account of the medium: [haze]'s visibility, or [atmosphere]'s parts.
std::string haze_text(const renderer::Haze& h) {
  if (!h.enabled) return "none";
  if (!h.column)
    return fmt::format("visibility {} m, scale height {} m", h.visibility, h.scale_height);
  std::string out = "atmosphere: U.S. Standard";
  if (h.column->scattering) out += ", Rayleigh";
  if (h.column->absorption)
    out += h.column->ozone_column > 0.0 ? fmt::format(", ozone {} DU", h.column->ozone_column)
                                        : std::string(", ozone");
  if (!h.aerosol) return out + ", no aerosol";
  out += h.aerosol_optical_depth
             ? fmt::format(", aerosol optical depth {}", *h.aerosol_optical_depth)
             : fmt::format(", aerosol visibility {} m", h.visibility);
  return out + (h.aerosol_profile == renderer::AerosolProfile::uniform
                    ? fmt::format(" uniform {}-{} m", h.uniform_bottom, h.uniform_top)
                    : fmt::format(", scale height {} m", h.scale_height));
}

std::string sky_text(const renderer::Sky& sky) {
  switch (sky.model) {
    case renderer::SkyKind::hosek_wilkie:
      return fmt::format("hosek-wilkie turbidity {}", sky.turbidity);
    case renderer::SkyKind::preetham:
      return fmt::format("preetham turbidity {}", sky.turbidity);
    case renderer::SkyKind::none:
      return "none";
    case renderer::SkyKind::atmosphere:
      return "atmosphere";
    case renderer::SkyKind::gradient:
      break;
  }
  return "gradient";
}

// The sensor bands every image holds as layers band.<name> (docs/SPECTRAL.md).
nlohmann::json bands_json(const Scenario& s) {
  nlohmann::json out = nlohmann::json::array();
  for (const BandSettings& b : s.bands)
    out.push_back({{"name", b.name},
                   {"layer", "band." + b.name},
                   {"definition", b.description},
                   {"unit", renderer::kBandUnit}});
  return out;
}

nlohmann::json box_json(const std::optional<renderer::PixelBox>& b) {
  if (!b) return nullptr;
  return {{"x0", (*b)[0]}, {"y0", (*b)[1]}, {"x1", (*b)[2]}, {"y1", (*b)[3]}};
}

// An object's oriented box (terrain frame, and the camera's: OpenCV's axes).
nlohmann::json box3d_json(const renderer::ObjectBox& b, const Vec3& origin) {
  const auto& m = b.rotation_camera;
  return {{"centre", vec_json(b.centre + origin)},
          {"size_m", vec_json(b.size)},
          {"heading_deg", b.heading_deg},
          {"pitch_deg", b.pitch_deg},
          {"roll_deg", b.roll_deg},
          {"centre_camera", vec_json(b.centre_camera)},
          {"rotation_camera", {{m[0], m[1], m[2]}, {m[3], m[4], m[5]}, {m[6], m[7], m[8]}}}};
}

std::string haze_phase(renderer::AerosolPhase p) {
  switch (p) {
    case renderer::AerosolPhase::isotropic:
      return "isotropic";
    case renderer::AerosolPhase::rayleigh:
      return "rayleigh";
    case renderer::AerosolPhase::table:
      return "table";
    case renderer::AerosolPhase::legendre:
      return "legendre";
    case renderer::AerosolPhase::henyey_greenstein:
      break;
  }
  return "henyey-greenstein";
}

// [atmosphere]: what it holds and, from the lowest ground, its vertical optical depths at
// 550 nm (what Beer-Lambert takes the beam through, docs/ATMOSPHERE.md "One atmosphere").
nlohmann::json atmosphere_json(const renderer::Scene& scene) {
  const renderer::Haze& h = scene.haze;
  if (!h.enabled || !h.column) return nullptr;
  const renderer::Medium medium(h, scene.spectral_grid);
  nlohmann::json out = {{"profile", "us-standard"},
                        {"rayleigh", h.column->scattering},
                        {"ozone", h.column->absorption},
                        {"earth_sun_distance_au", scene.sun.earth_sun_distance}};
  if (h.column->ozone_column > 0.0) out["ozone_column_du"] = h.column->ozone_column;
  const char* names[renderer::kMediumComponents] = {"aerosol", "rayleigh", "ozone"};
  nlohmann::json depths = nlohmann::json::object();
  for (int c = 0; c < renderer::kMediumComponents; ++c)
    if (medium.component(c).present) depths[names[c]] = medium.vertical_depth(c, h.base_height);
  out["optical_depth_550nm"] = depths;
  if (h.aerosol) {
    nlohmann::json a = {{"profile", h.aerosol_profile == renderer::AerosolProfile::uniform
                                        ? "uniform"
                                        : "exponential"}};
    if (!h.aerosol_model.empty()) {
      a["type"] = h.aerosol_model;  // its optics by wavelength
    } else {
      a["type"] = "continental-average";
      a["single_scattering_albedo"] = {h.albedo.x, h.albedo.y, h.albedo.z};
      a["phase"] = haze_phase(h.phase);
      a["angstrom"] = h.angstrom;
      if (h.phase == renderer::AerosolPhase::henyey_greenstein) a["asymmetry"] = h.asymmetry;
    }
    if (h.aerosol_optical_depth)
      a["optical_depth"] = *h.aerosol_optical_depth;
    else
      a["visibility_m"] = h.visibility;
    if (h.aerosol_profile == renderer::AerosolProfile::uniform)
      a["bottom_top_m"] = {h.uniform_bottom, h.uniform_top};
    else
      a["scale_height_m"] = h.scale_height;
    out["aerosol"] = a;
  }
  return out;
}

nlohmann::json haze_json(const renderer::Haze& h) {
  if (!h.enabled || h.column) return nullptr;
  nlohmann::json out = {
      {"single_scattering_albedo", {h.albedo.x, h.albedo.y, h.albedo.z}},
      {"phase", haze_phase(h.phase)},
      {"multiple_scattering", h.scattering == renderer::HazeScattering::paths ? "paths" : "table"}};
  if (h.phase == renderer::AerosolPhase::henyey_greenstein) out["asymmetry"] = h.asymmetry;
  if (h.layer) {
    out["layer"] = {{"optical_depth", h.layer->optical_depth}, {"top_m", h.layer->top}};
    return out;
  }
  out["visibility_m"] = h.visibility;
  out["scale_height_m"] = h.scale_height;
  out["angstrom"] = h.angstrom;
  out["molecular"] = h.molecular;
  return out;
}

}  // namespace

nlohmann::json randomised_json(std::size_t image, const std::vector<std::string>& set) {
  return {{"image", image}, {"set", set}};
}

nlohmann::json settings_json(const Scenario& s, const renderer::Scene& scene) {
  static const char* const kSeasons[] = {"spring", "summer", "autumn", "winter"};
  const Vec3f& e = scene.sun.irradiance;
  return {
      {"scenario_hash", s.text_hash},
      {"sun",
       {{"elevation_deg", s.sun.elevation_deg},
        {"azimuth_deg", s.sun.azimuth_deg},
        {"direction", vec_json(scene.sun.direction)},
        {"irradiance_lux", {e.x, e.y, e.z}}}},
      {"sky", sky_text(s.sky)},
      {"haze", haze_json(scene.haze)},
      {"atmosphere", atmosphere_json(scene)},
      {"wind",
       {{"speed", s.wind.speed}, {"gust", s.wind.gust}, {"direction_deg", s.wind.direction_deg}}},
      {"render",
       {{"spp", s.render.spp},
        {"noise_threshold", s.render.noise_threshold},
        {"seed", s.render.seed},
        {"sampling_seed", scene.settings.seed},
        {"max_bounces", s.render.max_bounces},
        {"season", kSeasons[static_cast<int>(s.render.season)]},
        {"degradation", s.render.degradation},
        {"guiding", s.render.guiding},
        {"guiding_training", s.render.guiding_training},
        {"quality", s.render.quality},
        {"exposure_ev100", s.render.exposure_ev100 ? nlohmann::json(*s.render.exposure_ev100)
                                                   : nlohmann::json("auto")}}}};
}

// The whole camera model (docs/CAMERAS.md), positions and axes in terrain coordinates: in the
// manifest and, as JSON text, the EXR's "camera" attribute.
nlohmann::json camera_json(const renderer::View& v, const Vec3& origin) {
  const renderer::Camera camera(v);
  const renderer::CameraBasis b = renderer::camera_basis(v);
  const renderer::Lens& l = v.lens;
  nlohmann::json out = {{"projection", renderer::projection_name(l.projection)},
                        {"position", vec_json(v.position + origin)},
                        {"target", vec_json(v.target + origin)},
                        {"forward", vec_json(b.forward)},
                        {"up", vec_json(b.up)},
                        {"right", vec_json(b.right)},
                        {"roll_deg", v.roll_deg},
                        {"width", v.width},
                        {"height", v.height}};
  using renderer::Projection;
  if (l.projection == Projection::orthographic) {
    out["extent_m"] = {l.extent_width, l.extent_height};
    return out;
  }
  if (l.projection == Projection::spherical) return out;
  out["fov_y_deg"] = v.fov_y_deg;
  const std::array<double, 9> k = camera.intrinsics();
  out["K"] = {{k[0], k[1], k[2]}, {k[3], k[4], k[5]}, {k[6], k[7], k[8]}};
  out["principal_point_offset_px"] = {l.principal_x, l.principal_y};
  if (l.sensor_width > 0)
    out["sensor_region"] = {{"sensor_pixels", {l.sensor_width, l.sensor_height}},
                            {"origin_px", {l.region_x0, l.region_y0}}};
  if (l.focal_length_mm > 0.0) out["focal_length_mm"] = l.focal_length_mm;
  if (l.projection != Projection::perspective) return out;
  const renderer::Distortion& d = l.distortion;
  out["distortion"] = {{"model", "opencv brown-conrady"},
                       {"k1", d.k1},
                       {"k2", d.k2},
                       {"k3", d.k3},
                       {"p1", d.p1},
                       {"p2", d.p2}};
  if (l.aperture_radius > 0.0) {
    out["f_number"] = l.f_number;
    out["focus_distance_m"] = l.focus_distance;
  }
  return out;
}

// The EXR header's description of the image: what made it.
// `camera`: camera_json of the view.
renderer::ImageMetadata metadata(const Scenario& s, const renderer::View& v,
                                 const renderer::Scene& scene, const nlohmann::json& camera) {
  const Vec3& sun = scene.sun.direction;
  renderer::ImageMetadata out = {{"version", LANDSIM_VERSION},
                                 {"scenario", s.source},
                                 {"scenario_hash", s.text_hash},
                                 {"view", v.name},
                                 {"camera_position", vec_text(v.position + scene.origin)},
                                 {"camera_target", vec_text(v.target + scene.origin)},
                                 {"fov_y_deg", fmt::format("{}", v.fov_y_deg)},
                                 {"camera", camera.dump()},
                                 {"legend", legend(s).dump()},
                                 {"scene_origin", vec_text(scene.origin)},
                                 {"sun_elevation_deg", fmt::format("{}", s.sun.elevation_deg)},
                                 {"sun_azimuth_deg", fmt::format("{}", s.sun.azimuth_deg)},
                                 {"sun_direction", vec_text(sun)},
                                 {"sky", sky_text(s.sky)},
                                 {"haze", haze_text(s.haze)},
                                 {"spp", std::to_string(s.render.spp)},
                                 {"noise_threshold", fmt::format("{}", s.render.noise_threshold)},
                                 {"seed", std::to_string(s.render.seed)},
                                 {"sampling_seed", std::to_string(scene.settings.seed)}};
  // What each band layer measures: its box or response file.
  for (const BandSettings& b : s.bands) out.emplace_back("band." + b.name, b.description);
  return out;
}

// `complete`: false when a later image failed; the manifest then lists the images finished
// before it, so that a set is never left without one (resume continues it).
void write_manifest(const std::filesystem::path& path, const Scenario& s,
                    const nlohmann::json& images, bool complete) {
  const nlohmann::json manifest = {
      {"complete", complete},
      {"scenario", s.source},
      {"version", LANDSIM_VERSION},
      {"spp", s.render.spp},
      {"seed", s.render.seed},
      {"sampling_seed", s.render.sampling_seed.value_or(s.render.seed)},
      {"sun", {{"elevation_deg", s.sun.elevation_deg}, {"azimuth_deg", s.sun.azimuth_deg}}},
      {"wind", {{"speed", s.wind.speed}, {"gust", s.wind.gust}}},
      {"bands", bands_json(s)},
      {"legend", legend(s)},
      {"images", images}};
  write_file_atomically(path, manifest.dump(2) + "\n");
}

// `camera`: camera_json of the image's placed view.
nlohmann::json manifest_entry(const ViewSettings& vs, const std::string& stem, std::size_t f,
                              double time, nlohmann::json camera) {
  return {{"path", stem + ".exr"}, {"preview", stem + ".png"}, {"view", vs.name},
          {"frame_index", f},      {"time_s", time},           {"camera", std::move(camera)}};
}

// The manifest's truth about each object in an image (docs/OBJECTS.md "Truth").
nlohmann::json objects_json(const std::vector<renderer::ObjectTruth>& truth, const Vec3& origin) {
  nlohmann::json out = nlohmann::json::array();
  for (std::size_t i = 0; i < truth.size(); ++i) {
    const renderer::ObjectTruth& t = truth[i];
    // The class, the mesh file's stem: a randomised set may draw the file per image.
    out.push_back({{"name", t.name},
                   {"class", std::filesystem::path(t.mesh).stem().string()},
                   {"target", i + 1},
                   {"visible_pixels", t.visible_pixels},
                   {"visible_coverage", t.visible_coverage},
                   {"footprint_pixels", t.footprint_pixels},
                   {"footprint_coverage", t.footprint_coverage},
                   {"coverage_threshold", 0.0},
                   {"visible_fraction", t.visible_fraction},
                   {"bbox", box_json(t.bbox)},
                   {"footprint_bbox", box_json(t.footprint_bbox)},
                   {"footprint_mask", t.footprint_rle},
                   {"range_m", t.range},
                   {"truncation", t.truncation ? nlohmann::json(*t.truncation) : nlohmann::json()},
                   {"box3d", box3d_json(t.box, origin)},
                   {"luminance", t.luminance},
                   {"background_luminance", t.background_luminance},
                   {"background_pixels", t.background_pixels},
                   {"ring_width", t.ring_width},
                   {"contrast", t.contrast ? nlohmann::json(*t.contrast) : nlohmann::json()}});
  }
  return out;
}

nlohmann::json noise_json(const renderer::Film& film, SampleSequence sampler) {
  const std::optional<renderer::ImageNoise> n = renderer::image_noise(film);
  if (!n) return nullptr;
  return {{"relative_mse", n->relative_mse},
          {"frame_relative_se", n->frame_relative_se},
          {"pixel_relative_se_median", n->pixel_relative_se_median},
          {"pixel_relative_se_p95", n->pixel_relative_se_p95},
          {"mean_spp", n->mean_spp},
          {"upper_bound", sampler == SampleSequence::sobol}};
}

// A JSON attribute (objects, camera) of an image already written; null when it has none.
nlohmann::json saved_json(const std::filesystem::path& exr, const std::string& attribute) {
  for (const auto& [key, value] : renderer::read_exr_metadata(exr))
    if (key == attribute) return nlohmann::json::parse(value, nullptr, false);
  return nullptr;
}

// The image's irradiance as the manifest and the EXR give it (docs/SENSOR.md).
nlohmann::json irradiance_json(const renderer::ImageIrradiance& e, const renderer::Scene& scene) {
  const auto rgb = [](const Vec3f& c) { return nlohmann::json::array({c.x, c.y, c.z}); };
  nlohmann::json layers = nlohmann::json::object();
  for (std::size_t b = 0; b < scene.bands.size(); ++b)
    layers[renderer::band_layer(scene.bands[b].name)] = e.layers[b];
  return {{"height_m", e.height + scene.origin.z},
          {"rgb", rgb(e.rgb)},
          {"illuminance_lux", renderer::rec709_luminance(Vec3(e.rgb))},
          {"direct_rgb", rgb(e.direct_rgb)},
          {"diffuse_rgb", rgb(e.diffuse_rgb)},
          {"layers", layers},
          {"unit", "rgb: lux-scaled Rec. 709; band.*: W m-2; photons.*: photons s-1 m-2"}};
}

// The manifest entry of an image already written, from what its EXR keeps.
nlohmann::json saved_entry(const Scenario& s, std::size_t view, const std::string& stem,
                           std::size_t frame, const std::filesystem::path& exr) {
  nlohmann::json entry =
      manifest_entry(s.views[view], stem, frame, s.render.frames[frame], saved_json(exr, "camera"));
  if (!s.objects.empty()) entry["objects"] = saved_json(exr, "objects");
  entry["irradiance"] = saved_json(exr, "irradiance");
  entry["noise"] = saved_json(exr, "noise");
  if (s.views[view].sensor) entry["sensor"] = saved_json(exr, "sensor");
  entry["settings"] = saved_json(exr, "settings");
  if (s.variation > 0) entry["randomised"] = randomised_json(s.variation - 1, s.variation_sets);
  return entry;
}

}  // namespace landsim::scenes::detail
