#include "scenes/scenario/detail/view_reader.h"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <numbers>
#include <regex>

#include "core/input_error.h"
#include "params/table_reader.h"
#include "renderer/camera.h"
#include "renderer/lens_distortion.h"
#include "scenes/scenario/detail/sensor_reader.h"

namespace landsim::scenes::detail {
namespace {

using params::Range;
using params::TableReader;
using renderer::is_fisheye;
using renderer::Projection;

constexpr double kDegree = std::numbers::pi / 180.0;
const Range kCoordinate{-1e12, 1e12};

// Refuses `key` where the projection has no use for it.
void only_for(TableReader& r, std::string_view key, bool applies, const std::string& which) {
  if (!applies && r.has(key)) r.fail(key, "applies to " + which + " only");
}

Projection read_projection(TableReader& r) {
  const std::string p = r.choice(
      "projection", {"perspective", "orthographic", "fisheye", "spherical"}, "perspective");
  only_for(r, "mapping", p == "fisheye", "projection = \"fisheye\"");
  if (p == "fisheye")
    return r.choice("mapping", {"equidistant", "equisolid"}, "equidistant") == "equisolid"
               ? Projection::fisheye_equisolid
               : Projection::fisheye_equidistant;
  if (p == "orthographic") return Projection::orthographic;
  return p == "spherical" ? Projection::spherical : Projection::perspective;
}

void read_size(TableReader& r, ViewSettings& v) {
  v.has_size = r.has("width") || r.has("height") || v.grid_cells_per_pixel == 0;
  if (!v.has_size) return;  // the grid's own size, in scenes/builder/view_placement
  v.width = static_cast<int>(r.integer("width", 1, kMaxImageSide, v.width));
  v.height = static_cast<int>(r.integer("height", 1, kMaxImageSide, v.height));
  try {
    check_image_size(v.width, v.height, "");
  } catch (const InputError& e) {
    r.fail("width", e.what());
  }
}

void read_placement(TableReader& r, ViewSettings& v) {
  only_for(r, "align", v.lens.projection == Projection::orthographic,
           "projection = \"orthographic\"");
  if (r.choice("align", {"none", "grid"}, "none") == "grid")
    v.grid_cells_per_pixel = static_cast<int>(r.integer("cells_per_pixel", 1, 4096, 1));
  only_for(r, "cells_per_pixel", v.grid_cells_per_pixel > 0, "align = \"grid\"");
  v.altitude_above_ground = r.optional_number("altitude_above_ground", Range{0.0, 1e7});
  if (v.altitude_above_ground) {
    const std::vector<double> xy = r.numbers("position", 2, kCoordinate);
    v.position = {xy[0], xy[1], 0.0};
  } else if (v.grid_cells_per_pixel > 0 && !r.has("position")) {
    v.has_position = false;
  } else {
    v.position = r.vec3("position", kCoordinate);
  }
}

// The optical axis: exactly one of target, direction, or yaw and pitch (orthographic views
// look straight down by default).
void read_axis(TableReader& r, ViewSettings& v) {
  const int given =
      int{r.has("target")} + int{r.has("direction")} + int{r.has("yaw") || r.has("pitch")};
  if (given > 1)
    r.fail(r.has("direction") ? "direction" : "yaw",
           "give one of target, direction, or yaw and pitch");
  v.aims_at_point = r.has("target");
  if (v.aims_at_point) {
    v.target = r.vec3("target", kCoordinate);
    if (v.has_position && !v.altitude_above_ground && length(v.target - v.position) < 1e-6)
      r.fail("target", "must differ from position");
    return;
  }
  Vec3 d{0.0, 0.0, -1.0};
  if (r.has("direction")) {
    d = r.vec3("direction", Range{-1e6, 1e6});
    if (length(d) < 1e-12) r.fail("direction", "must not be zero");
    d = normalize(d);
  } else if (r.has("yaw") || r.has("pitch")) {
    v.heading_deg = r.number("yaw", Range{-360.0, 360.0}, 0.0);
    const double pitch = r.number("pitch", Range{-90.0, 90.0}) * kDegree;
    const double yaw = v.heading_deg * kDegree;
    d = {std::sin(yaw) * std::cos(pitch), std::cos(yaw) * std::cos(pitch), -std::sin(pitch)};
  } else if (v.lens.projection != Projection::orthographic) {
    r.fail("target", "expected target, direction, or yaw and pitch (the way the camera looks)");
  }
  v.target = v.position + 1000.0 * d;  // moves with the position (scenes/builder/view_placement)
}

void read_up(TableReader& r, ViewSettings& v) {
  v.roll_deg = r.number("roll", Range{-360.0, 360.0}, 0.0);
  if (!r.has("up")) return;
  const Vec3 up = r.vec3("up", Range{-1e6, 1e6});
  if (length(up) < 1e-12) r.fail("up", "must not be zero");
  v.up = normalize(up);
  const Vec3 axis = v.target - v.position;
  if (v.has_position && !v.altitude_above_ground && length(cross(normalize(axis), v.up)) < 1e-6)
    r.fail("up", "is parallel to the view's axis; the image's up needs a direction across it");
}

// Pixel pitch in millimetres (x, y) from sensor_size or pixel_pitch; empty when neither.
std::optional<std::pair<double, double>> read_pitch(TableReader& r, const ViewSettings& v) {
  if (r.has("sensor_size") && r.has("pixel_pitch"))
    r.fail("pixel_pitch", "give sensor_size or pixel_pitch, not both");
  if (r.has("sensor_size")) {
    // Of the whole sensor when the image is a region of it (sensor_pixels).
    const std::vector<double> s = r.numbers("sensor_size", 2, Range{0.0, 1e4, true});
    const auto full = r.optional_numbers("sensor_pixels", 2, Range{1.0, 1e6});
    return full ? std::pair{s[0] / (*full)[0], s[1] / (*full)[1]}
                : std::pair{s[0] / v.width, s[1] / v.height};
  }
  if (r.has("pixel_pitch")) {
    const double um = r.number("pixel_pitch", Range{0.0, 1e5, true});
    return std::pair{um / 1000.0, um / 1000.0};
  }
  return std::nullopt;
}

void read_perspective(TableReader& r, ViewSettings& v) {
  if (!r.has("focal_length")) {
    for (const char* k : {"sensor_size", "pixel_pitch"})
      if (r.has(k)) r.fail(k, "needs focal_length (mm): together they give the field of view");
    v.fov_y_deg = r.number("fov", Range{0.0, 180.0, true, true}, v.fov_y_deg);
    return;
  }
  if (r.has("fov")) r.fail("fov", "give fov or focal_length, not both");
  v.lens.focal_length_mm = r.number("focal_length", Range{0.0, 1e5, true});
  const auto pitch = read_pitch(r, v);
  if (!pitch) r.fail("focal_length", "needs sensor_size (mm, width x height) or pixel_pitch (um)");
  v.fov_y_deg = 2.0 * std::atan(0.5 * v.height * pitch->second / v.lens.focal_length_mm) / kDegree;
  v.lens.fx_over_fy = pitch->second / pitch->first;
}

// A region of a larger sensor (sensor_pixels, region_centre): the image is width x height
// of the sensor's pixels around region_centre, seen through the whole sensor's lens: its
// pitch and focal length as given, the optical axis at the sensor's centre (plus
// principal_point), so the region's principal point is offset by the centre's distance.
void read_region(TableReader& r, ViewSettings& v) {
  const auto full = r.optional_numbers("sensor_pixels", 2, Range{1.0, 1e6});
  if (!full) {
    if (r.has("region_centre")) r.fail("region_centre", "needs sensor_pixels (the whole sensor)");
    return;
  }
  if (v.lens.focal_length_mm <= 0.0)
    r.fail("sensor_pixels",
           "needs focal_length with pixel_pitch or sensor_size: the region is "
           "seen through the whole sensor's lens");
  const double w = (*full)[0], h = (*full)[1];
  if (w != std::floor(w) || h != std::floor(h) || v.width > w || v.height > h)
    r.fail("sensor_pixels",
           fmt::format("expected whole pixels holding the {} x {} image", v.width, v.height));
  const std::vector<double> c =
      r.numbers("region_centre", 2, Range{0.0, 1e6}, std::vector<double>{0.5 * w, 0.5 * h});
  const double x0 = c[0] - 0.5 * v.width, y0 = c[1] - 0.5 * v.height;
  if (x0 < 0.0 || y0 < 0.0 || x0 + v.width > w || y0 + v.height > h)
    r.fail("region_centre", fmt::format("the {} x {} region around ({}, {}) leaves the {} x {} "
                                        "sensor",
                                        v.width, v.height, c[0], c[1], w, h));
  v.lens.sensor_width = static_cast<int>(w);
  v.lens.sensor_height = static_cast<int>(h);
  v.lens.region_x0 = x0;
  v.lens.region_y0 = y0;
  v.lens.principal_x += 0.5 * w - c[0];
  v.lens.principal_y += 0.5 * h - c[1];
}

void read_fisheye(TableReader& r, ViewSettings& v) {
  v.fov_y_deg = r.number("fov", Range{0.0, 220.0, true}, 180.0);
  const double half = 0.5 * v.fov_y_deg * kDegree;
  const bool equidistant = v.lens.projection == Projection::fisheye_equidistant;
  if (r.has("focal_length")) {
    if (r.has("image_circle"))
      r.fail("image_circle", "give image_circle or focal_length, not both");
    v.lens.focal_length_mm = r.number("focal_length", Range{0.0, 1e5, true});
    const auto pitch = read_pitch(r, v);
    if (!pitch)
      r.fail("focal_length", "needs sensor_size (mm, width x height) or pixel_pitch (um)");
    v.lens.fisheye_focal = v.lens.focal_length_mm / pitch->second;
    return;
  }
  for (const char* k : {"sensor_size", "pixel_pitch"})
    if (r.has(k)) r.fail(k, "needs focal_length (mm)");
  const double circle =
      r.number("image_circle", Range{0.0, 1e6, true}, std::min(v.width, v.height));
  v.lens.fisheye_focal = 0.5 * circle / (equidistant ? half : 2.0 * std::sin(0.5 * half));
}

void read_orthographic(TableReader& r, ViewSettings& v) {
  if (v.grid_cells_per_pixel > 0) {
    for (const char* k : {"extent", "pixel_size"})
      if (r.has(k)) r.fail(k, "align = \"grid\" sets the pixel size from cells_per_pixel");
    return;
  }
  if (r.has("extent") && r.has("pixel_size"))
    r.fail("pixel_size", "give extent or pixel_size, not both");
  if (r.has("pixel_size")) {
    const double p = r.number("pixel_size", Range{0.0, 1e6, true});
    v.lens.extent_width = p * v.width;
    v.lens.extent_height = p * v.height;
    return;
  }
  if (!r.has("extent"))
    r.fail("extent",
           "projection = \"orthographic\" needs extent ([width, height], metres), "
           "pixel_size (metres) or align = \"grid\"");
  const std::vector<double> e = r.numbers("extent", 2, Range{0.0, 1e8, true});
  v.lens.extent_width = e[0];
  v.lens.extent_height = e[1];
}

void read_intrinsics(TableReader& r, ViewSettings& v) {
  const Projection p = v.lens.projection;
  const std::string which = "perspective and fisheye projections";
  for (const char* k : {"fov", "focal_length", "sensor_size", "pixel_pitch", "principal_point"})
    only_for(r, k, p == Projection::perspective || is_fisheye(p), which);
  only_for(r, "image_circle", is_fisheye(p), "projection = \"fisheye\"");
  for (const char* k : {"extent", "pixel_size"})
    only_for(r, k, p == Projection::orthographic, "projection = \"orthographic\"");
  if (p == Projection::perspective) read_perspective(r, v);
  if (is_fisheye(p)) read_fisheye(r, v);
  if (p == Projection::orthographic) read_orthographic(r, v);
  if (const auto pp = r.optional_numbers("principal_point", 2, Range{-1e6, 1e6})) {
    v.lens.principal_x = (*pp)[0];
    v.lens.principal_y = (*pp)[1];
  }
  for (const char* k : {"sensor_pixels", "region_centre"})
    only_for(r, k, p == Projection::perspective, "perspective projections");
  if (p == Projection::perspective) read_region(r, v);
}

// The distorted normalised radius of the frame's farthest corner.
double frame_radius(const ViewSettings& v) {
  // K in OpenCV's convention: the frame's corners are half a pixel outside the outer centres.
  const std::array<double, 9> k = renderer::Camera(v).intrinsics();
  double r = 0.0;
  for (const double x : {-0.5, v.width - 0.5})
    for (const double y : {-0.5, v.height - 0.5})
      r = std::max(r, std::hypot((x - k[2]) / k[0], (y - k[5]) / k[4]));
  return r;
}

void read_distortion(TableReader& r, ViewSettings& v) {
  only_for(r, "distortion", v.lens.projection == Projection::perspective,
           "projection = \"perspective\"");
  if (!r.has("distortion")) return;
  TableReader d = r.table("distortion");
  const Range k{-1e3, 1e3};
  renderer::Distortion& c = v.lens.distortion;
  c.k1 = d.number("k1", k, 0.0);
  c.k2 = d.number("k2", k, 0.0);
  c.k3 = d.number("k3", k, 0.0);
  c.p1 = d.number("p1", Range{-1.0, 1.0}, 0.0);
  c.p2 = d.number("p2", Range{-1.0, 1.0}, 0.0);
  d.finish();
  if (!renderer::unfolded_within(c, frame_radius(v)))
    r.fail("distortion",
           "folds the image: the radial distortion stops growing (or never "
           "reaches the frame's corners) inside the frame, so one pixel would see "
           "two directions");
}

void read_aperture(TableReader& r, ViewSettings& v) {
  only_for(r, "f_number", v.lens.projection == Projection::perspective,
           "projection = \"perspective\"");
  only_for(r, "focus_distance", r.has("f_number"), "a thin lens (f_number)");
  if (!r.has("f_number")) return;
  v.lens.f_number = r.number("f_number", Range{0.5, 1e4});
  if (v.lens.focal_length_mm <= 0.0)
    r.fail("f_number", "needs focal_length (mm): the aperture is focal_length / f_number");
  v.lens.aperture_radius = 0.5 * v.lens.focal_length_mm / 1000.0 / v.lens.f_number;
  if (!r.has("focus_distance") && !v.aims_at_point)
    r.fail("f_number", "needs focus_distance (metres) when the view has no target");
  const double to_target = length(v.target - v.position);
  v.lens.focus_distance = r.number("focus_distance", Range{0.0, 1e9, true},
                                   v.aims_at_point ? std::optional(to_target) : std::nullopt);
}

}  // namespace

ViewSettings read_view(const toml::table& t, const std::string& path, const std::string& file,
                       const std::optional<SensorSettings>& sensor) {
  TableReader r(t, path, file);
  ViewSettings v;
  v.name = r.string("name");
  static const std::regex kName("[A-Za-z0-9_.-]+");
  if (!std::regex_match(v.name, kName) || v.name[0] == '.') {
    r.fail("name", "expected letters, digits, '_', '-' or '.' (it names the output files), got \"" +
                       v.name + "\"");
  }
  v.lens.projection = read_projection(r);
  read_placement(r, v);
  read_size(r, v);
  read_axis(r, v);
  read_up(r, v);
  read_intrinsics(r, v);
  read_distortion(r, v);
  read_aperture(r, v);
  v.sensor = read_view_sensor(r, sensor, v);
  r.finish();
  return v;
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
    views.push_back(read_view(*a->get(i)->as_table(), path, file, sensor));
    const TableReader located(*a->get(i)->as_table(), path, file);
    views.back().location = located.location(a->get(i)->as_table()->get("position"));
    if (!names.insert(views.back().name).second) {
      TableReader(*a->get(i)->as_table(), path, file)
          .fail("name", "duplicate view name \"" + views.back().name + "\"");
    }
  }
  return views;
}

}  // namespace landsim::scenes::detail
