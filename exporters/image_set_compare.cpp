#include "exporters/image_set_compare.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>

#include "core/atomic_file.h"
#include "core/input_error.h"
#include "renderer/output/film.h"
#include "renderer/output/image_output.h"
#include "scenes/image_set/image_set.h"

namespace landsim::exporters {
namespace {

constexpr int kRegions = 8;

struct Entry {
  std::string view;
  int frame = 0;
  std::string path;
};

std::string label(const std::string& view, int frame) { return fmt::format("{} f{}", view, frame); }

// The images a set's manifest lists, by (view, frame).
std::map<std::pair<std::string, int>, Entry> manifest(
    const std::filesystem::path& dir, std::vector<std::pair<std::string, int>>& order) {
  const std::filesystem::path file = dir / "manifest.json";
  const nlohmann::json j = scenes::read_manifest(dir);
  std::map<std::pair<std::string, int>, Entry> out;
  for (const nlohmann::json& image : j["images"]) {
    if (!image.is_object() || !image.contains("path") || !image["path"].is_string() ||
        !image.contains("view") || !image["view"].is_string() || !image.contains("frame_index") ||
        !image["frame_index"].is_number_integer())
      throw InputError(file.string() +
                       ": an image without a path, view (strings) or frame_index (an integer) "
                       "(expected landsim's manifest)");
    Entry e{image["view"].get<std::string>(), image["frame_index"].get<int>(),
            image["path"].get<std::string>()};
    const auto key = std::pair{e.view, e.frame};
    if (out.emplace(key, e).second) order.push_back(key);
  }
  return out;
}

renderer::Film read(const std::filesystem::path& file) {
  try {
    return renderer::read_exr(file);
  } catch (const std::exception& e) {
    throw InputError(file.string() + ": cannot read the image: " + e.what());
  }
}

double relative(double a, double b) {
  return b > 0.0 ? std::abs(a - b) / b : (a > 0.0 ? 1.0 : 0.0);
}

void compare_luminance(const renderer::Film& a, const renderer::Film& b, ImageDifference& d) {
  const int w = a.width(), h = a.height();
  double sum_a = 0.0, sum_b = 0.0;
  std::vector<double> ra(kRegions * kRegions, 0.0), rb(ra.size(), 0.0);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const double la = a.luminance(x, y), lb = b.luminance(x, y);
      sum_a += la;
      sum_b += lb;
      const auto r = static_cast<std::size_t>(region_index(x, y, w, h, kRegions));
      ra[r] += la;
      rb[r] += lb;
    }
  d.luminance_mean_rel_diff = relative(sum_a, sum_b);
  for (std::size_t r = 0; r < ra.size(); ++r)
    d.luminance_region_max_rel_diff =
        std::max(d.luminance_region_max_rel_diff, relative(ra[r], rb[r]));
}

void compare_layers(const renderer::Film& a, const renderer::Film& b, ImageDifference& d) {
  double depth = 0.0, angle = 0.0;
  std::size_t depth_n = 0, angle_n = 0, object = 0, species = 0;
  for (int y = 0; y < a.height(); ++y)
    for (int x = 0; x < a.width(); ++x) {
      const float da = a.depth(x, y), db = b.depth(x, y);
      if (std::isfinite(da) && std::isfinite(db) && db > 0.0f) {
        depth += std::abs(da - db) / db;
        ++depth_n;
      } else if (std::isfinite(da) != std::isfinite(db)) {
        depth += 1.0;  // a surface in one, sky in the other
        ++depth_n;
      }
      const Vec3f na = a.normal(x, y), nb = b.normal(x, y);
      if (length(na) > 0.0f && length(nb) > 0.0f) {
        // atan2 of |a x b| and a . b: exact for equal normals (acos of a rounded dot product
        // read 5.8e-5 degrees between identical files) and accurate at small angles.
        const Vec3 va(na), vb(nb);
        angle += std::atan2(length(cross(va, vb)), dot(va, vb)) * 180.0 / std::numbers::pi;
        ++angle_n;
      }
      object += a.object(x, y) != b.object(x, y);
      species += a.species(x, y) != b.species(x, y);
    }
  const auto n = static_cast<double>(a.pixel_count());
  d.depth_mean_rel_diff = depth_n > 0 ? depth / static_cast<double>(depth_n) : 0.0;
  d.normal_mean_angle_deg = angle_n > 0 ? angle / static_cast<double>(angle_n) : 0.0;
  d.object_mismatch = static_cast<double>(object) / n;
  d.species_mismatch = static_cast<double>(species) / n;
}

bool passes(const ImageDifference& d, const CompareOptions& o) {
  const bool luminance = o.statistical ? d.noise.within_noise
                                       : d.luminance_mean_rel_diff <= o.max_mean_diff &&
                                             d.luminance_region_max_rel_diff <= o.max_region_diff;
  return !d.size_mismatch && luminance && d.depth_mean_rel_diff <= o.max_layer_diff &&
         d.object_mismatch <= o.max_layer_diff && d.species_mismatch <= o.max_layer_diff &&
         d.normal_mean_angle_deg <= o.max_normal_deg;
}

nlohmann::json to_json(const ImageDifference& d) {
  return {{"view", d.view},
          {"frame_index", d.frame},
          {"path_a", d.path_a},
          {"path_b", d.path_b},
          {"size_mismatch", d.size_mismatch},
          {"luminance_mean_rel_diff", d.luminance_mean_rel_diff},
          {"luminance_region_max_rel_diff", d.luminance_region_max_rel_diff},
          {"depth_mean_rel_diff", d.depth_mean_rel_diff},
          {"normal_mean_angle_deg", d.normal_mean_angle_deg},
          {"object_mismatch", d.object_mismatch},
          {"species_mismatch", d.species_mismatch},
          {"noise_test", d.noise.available
                             ? nlohmann::json{{"image_z", d.noise.image_z},
                                              {"region_max_z", d.noise.region_max_z},
                                              {"image_threshold", d.noise.image_threshold},
                                              {"region_threshold", d.noise.region_threshold},
                                              {"within_noise", d.noise.within_noise}}
                             : nlohmann::json()},
          {"pass", d.pass}};
}

}  // namespace

SetComparison compare_image_sets(const std::filesystem::path& a, const std::filesystem::path& b,
                                 const CompareOptions& options) {
  std::vector<std::pair<std::string, int>> order_a, order_b;
  const auto set_a = manifest(a, order_a);
  const auto set_b = manifest(b, order_b);
  SetComparison c;
  for (const auto& key : order_a) {
    const auto other = set_b.find(key);
    if (other == set_b.end()) {
      c.only_in_a.push_back(label(key.first, key.second));
      continue;
    }
    ImageDifference d;
    d.view = key.first;
    d.frame = key.second;
    d.path_a = set_a.at(key).path;
    d.path_b = other->second.path;
    const renderer::Film fa = read(a / d.path_a), fb = read(b / d.path_b);
    d.size_mismatch = fa.width() != fb.width() || fa.height() != fb.height();
    if (!d.size_mismatch) {
      compare_luminance(fa, fb, d);
      compare_layers(fa, fb, d);
      d.noise = noise_test(fa, fb, options.alpha, kRegions);
      if (options.statistical && !d.noise.available)
        throw InputError(fmt::format(
            "{} or {}: no variance layer (Y.variance) to test against noise: render both with "
            "this landsim and at least 2 spp, or compare without --statistical",
            (a / d.path_a).string(), (b / d.path_b).string()));
    }
    d.pass = passes(d, options);
    c.images.push_back(d);
  }
  for (const auto& key : order_b)
    if (set_a.find(key) == set_a.end()) c.only_in_b.push_back(label(key.first, key.second));
  c.pass = c.only_in_a.empty() && c.only_in_b.empty() &&
           std::all_of(c.images.begin(), c.images.end(), [](const auto& d) { return d.pass; });
  return c;
}

std::string comparison_json(const SetComparison& c) {
  nlohmann::json images = nlohmann::json::array();
  for (const ImageDifference& d : c.images) images.push_back(to_json(d));
  return nlohmann::json{
      {"images", images}, {"only_in_a", c.only_in_a}, {"only_in_b", c.only_in_b}, {"pass", c.pass}}
      .dump();
}

void write_compare_reports(const SetComparison& c, const CompareOptions& o,
                           const std::filesystem::path& a, const std::filesystem::path& b,
                           const std::filesystem::path& dir) {
  std::filesystem::create_directories(dir);
  nlohmann::json images = nlohmann::json::array();
  for (const ImageDifference& d : c.images) images.push_back(to_json(d));
  const nlohmann::json j = {{"set_a", a.string()},
                            {"set_b", b.string()},
                            {"images", images},
                            {"only_in_a", c.only_in_a},
                            {"only_in_b", c.only_in_b},
                            {"thresholds",
                             {{"max_mean_diff", o.max_mean_diff},
                              {"max_region_diff", o.max_region_diff},
                              {"max_layer_diff", o.max_layer_diff},
                              {"max_normal_deg", o.max_normal_deg}}},
                            {"pass", c.pass}};
  { write_file_atomically(dir / "report.json", j.dump(2) + "\n"); }
  std::string rows;
  for (const ImageDifference& d : c.images)
    rows += fmt::format(
        "<tr><td>{}<td>{}<td>{}<td>{:.3f}%<td>{:.3f}%<td>{:.3f}%<td>{:.2f}<td>{:.3f}%<td>{:.3f}%\n",
        d.view, d.frame, d.pass ? "pass" : (d.size_mismatch ? "FAIL (sizes differ)" : "FAIL"),
        100 * d.luminance_mean_rel_diff, 100 * d.luminance_region_max_rel_diff,
        100 * d.depth_mean_rel_diff, d.normal_mean_angle_deg, 100 * d.object_mismatch,
        100 * d.species_mismatch);
  const auto list = [](const std::vector<std::string>& v) {
    std::string s;
    for (const std::string& x : v) s += (s.empty() ? "" : ", ") + x;
    return s.empty() ? std::string("none") : s;
  };
  write_file_atomically(
      dir / "report.html",
      fmt::format(
          "<!doctype html><meta charset=utf-8><title>landsim compare</title>\n"
          "<h1>{}: {} against {}</h1>\n<table><tr><th>view<th>frame<th>result<th>mean luminance"
          "<th>worst region<th>depth<th>normal (deg)<th>object<th>species\n{}</table>\n"
          "<p>Only in the first set: {}. Only in the second: {}.\n<p>Thresholds: mean {:.2f}%, "
          "region {:.2f}%, layers {:.2f}%, normals {:.2f} degrees.\n",
          c.pass ? "pass" : "FAIL", a.string(), b.string(), rows, list(c.only_in_a),
          list(c.only_in_b), 100 * o.max_mean_diff, 100 * o.max_region_diff, 100 * o.max_layer_diff,
          o.max_normal_deg));
}

}  // namespace landsim::exporters
