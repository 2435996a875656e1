#include "renderer/output/object_truth.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/counter_rng.h"
#include "renderer/acceleration/embree_scene.h"
#include "renderer/camera.h"
#include "renderer/transport/render.h"

namespace landsim::renderer {
namespace {

// An object's axis-aligned bounding box in the scene frame: low and high corners.
std::array<Vec3, 2> object_bounds(const Scene& scene, const ObjectInstance& o) {
  const ObjectPrototype& p = scene.object_prototypes[o.prototype];
  Vec3 lo{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
          std::numeric_limits<double>::infinity()};
  Vec3 hi = -lo;
  for (const Vec3f& v : p.vertices) {
    const Vec3 w = o.apply(v);
    lo = {std::min(lo.x, w.x), std::min(lo.y, w.y), std::min(lo.z, w.z)};
    hi = {std::max(hi.x, w.x), std::max(hi.y, w.y), std::max(hi.z, w.z)};
  }
  return {lo, hi};
}

// The image rectangle around an object's bounding box's projected corners, two pixels of
// margin (lens distortion and wide models bend edges between corners), unclamped: x0, y0,
// x1, y1; empty when a corner has no image position.
std::optional<std::array<double, 4>> projected_rectangle(const Scene& scene,
                                                         const ObjectInstance& o,
                                                         const Camera& camera) {
  const auto [lo, hi] = object_bounds(scene, o);
  std::array<double, 4> r{1e300, 1e300, -1e300, -1e300};
  for (int k = 0; k < 8; ++k) {
    const Vec3 c{k & 1 ? hi.x : lo.x, k & 2 ? hi.y : lo.y, k & 4 ? hi.z : lo.z};
    const std::optional<ImagePoint> at = camera.project(c);
    if (!at) return std::nullopt;
    r = {std::min(r[0], at->x), std::min(r[1], at->y), std::max(r[2], at->x),
         std::max(r[3], at->y)};
  }
  return std::array<double, 4>{std::floor(r[0]) - 2.0, std::floor(r[1]) - 2.0,
                               std::ceil(r[2]) + 2.0, std::ceil(r[3]) + 2.0};
}

// The pixels of the frame an object can cover (the whole frame when its rectangle is
// unknown; x1 < x0 when it lies wholly outside).
PixelBox projected_bounds(const Scene& scene, const ObjectInstance& o, const Camera& camera,
                          const View& view) {
  const auto r = projected_rectangle(scene, o, camera);
  if (!r) return {0, 0, view.width - 1, view.height - 1};
  const auto clamp_to = [](double v, int hi_index) {
    return static_cast<int>(std::clamp(v, 0.0, static_cast<double>(hi_index)));
  };
  if ((*r)[2] < 0.0 || (*r)[3] < 0.0 || (*r)[0] >= view.width || (*r)[1] >= view.height)
    return {0, 0, -1, -1};
  return {clamp_to((*r)[0], view.width - 1), clamp_to((*r)[1], view.height - 1),
          clamp_to((*r)[2], view.width - 1), clamp_to((*r)[3], view.height - 1)};
}

// The object's footprint coverage beyond the frame: the same rays continued past its edges
// (perspective and orthographic views only; empty for the others, and when the part beyond
// spans more than four frames).
std::optional<double> coverage_beyond_the_frame(const Scene& scene, std::size_t index,
                                                const EmbreeScene& objects, const Camera& camera,
                                                const View& view, int spp) {
  using renderer::Projection;
  if (view.lens.projection != Projection::perspective &&
      view.lens.projection != Projection::orthographic)
    return std::nullopt;
  const auto r = projected_rectangle(scene, scene.objects[index], camera);
  if (!r) return std::nullopt;
  const double area = ((*r)[2] - (*r)[0] + 1.0) * ((*r)[3] - (*r)[1] + 1.0);
  if (area > 4.0 * view.width * view.height) return std::nullopt;
  double sum = 0.0;
  for (int y = static_cast<int>((*r)[1]); y <= static_cast<int>((*r)[3]); ++y)
    for (int x = static_cast<int>((*r)[0]); x <= static_cast<int>((*r)[2]); ++x) {
      if (x >= 0 && y >= 0 && x < view.width && y < view.height) continue;
      // A key of its own for each pixel beyond the frame (in-frame keys are below 2^63).
      const std::uint64_t key = (std::uint64_t{1} << 63) |
                                (std::uint64_t{static_cast<std::uint32_t>(x)} << 32) |
                                static_cast<std::uint32_t>(y);
      for (int s = 0; s < spp; ++s) {
        const CounterRng rng(scene.settings.seed, key, static_cast<std::uint64_t>(s));
        const std::optional<Ray> ray = sample_ray(camera, rng, x, y, false);
        if (!ray) continue;
        const auto hit = objects.intersect(*ray, 0.0f, std::numeric_limits<float>::infinity());
        if (hit && hit->object_index == static_cast<std::int32_t>(index))
          sum += 1.0 / static_cast<double>(spp);
      }
    }
  return sum;
}

// Per pixel, the share of its samples whose ray meets each object in a scene of the objects
// alone (the render's own rays: sample_ray of every sample), as (object index, share) pairs.
struct FootprintHit {
  std::uint32_t object;
  float share;
};
struct Footprints {
  std::vector<std::vector<FootprintHit>> pixels;        // per pixel of the frame
  std::vector<std::optional<double>> beyond_the_frame;  // per object
};
Footprints footprints(const Scene& scene, const View& view, bool centre_first) {
  const EmbreeScene objects(scene, nullptr, EmbreeScene::Contents::objects_only);
  const Camera camera(view);
  std::vector<std::uint8_t> near(static_cast<std::size_t>(view.width) * view.height, 0);
  for (const ObjectInstance& o : scene.objects) {
    const PixelBox b = projected_bounds(scene, o, camera, view);
    for (int y = b[1]; y <= b[3]; ++y)
      for (int x = b[0]; x <= b[2]; ++x) near[static_cast<std::size_t>(y) * view.width + x] = 1;
  }
  Footprints result;
  std::vector<std::vector<FootprintHit>>& out = result.pixels;
  out.resize(near.size());
  const int spp = scene.settings.spp;
  tbb::parallel_for(0, view.height, [&](int y) {
    for (int x = 0; x < view.width; ++x) {
      const auto pixel = static_cast<std::uint64_t>(y) * static_cast<std::uint64_t>(view.width) +
                         static_cast<std::uint64_t>(x);
      if (!near[pixel]) continue;
      std::vector<FootprintHit>& hits = out[pixel];
      for (int s = 0; s < spp; ++s) {
        const std::optional<Ray> ray = sample_ray(camera, camera_ray_rng(scene.settings, pixel, s),
                                                  x, y, centre_first && s == 0);
        if (!ray) continue;
        const auto hit = objects.intersect(*ray, 0.0f, std::numeric_limits<float>::infinity());
        if (!hit || hit->object_index < 0) continue;
        const auto id = static_cast<std::uint32_t>(hit->object_index);
        auto it = std::find_if(hits.begin(), hits.end(),
                               [&](const FootprintHit& h) { return h.object == id; });
        if (it == hits.end()) it = hits.insert(hits.end(), {id, 0.0f});
        it->share += 1.0f / static_cast<float>(spp);
      }
    }
  });
  for (std::size_t i = 0; i < scene.objects.size(); ++i)
    result.beyond_the_frame.push_back(
        coverage_beyond_the_frame(scene, i, objects, camera, view, spp));
  return result;
}

// The object's oriented box: its mesh's bounds in its own frame (x right, y front, z up),
// carried into the scene frame, and seen from the camera.
ObjectBox object_box(const Scene& scene, const ObjectInstance& o, const View& view) {
  const ObjectPrototype& p = scene.object_prototypes[o.prototype];
  Vec3 lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
  for (const Vec3f& v : p.vertices) {
    lo = {std::min(lo.x, double{v.x}), std::min(lo.y, double{v.y}), std::min(lo.z, double{v.z})};
    hi = {std::max(hi.x, double{v.x}), std::max(hi.y, double{v.y}), std::max(hi.z, double{v.z})};
  }
  ObjectBox b;
  const double scale = length(o.turn({1.0, 0.0, 0.0}));
  b.size = (hi - lo) * scale;
  b.centre = o.apply(Vec3f((lo + hi) * 0.5));
  b.right = normalize(o.turn({1.0, 0.0, 0.0}));
  b.front = normalize(o.turn({0.0, 1.0, 0.0}));
  b.up = normalize(o.turn({0.0, 0.0, 1.0}));
  constexpr double kDegrees = 180.0 / 3.14159265358979323846;
  b.heading_deg = std::atan2(b.front.x, b.front.y) * kDegrees;
  b.pitch_deg = std::asin(std::clamp(b.front.z, -1.0, 1.0)) * kDegrees;
  b.roll_deg = std::atan2(-b.right.z, b.up.z) * kDegrees;
  // The camera frame as OpenCV's: x right, y down, z forward.
  const CameraBasis c = camera_basis(view);
  const auto camera_frame = [&](const Vec3& d) {
    return Vec3{dot(d, c.right), -dot(d, c.up), dot(d, c.forward)};
  };
  b.centre_camera = camera_frame(b.centre - view.position);
  const Vec3 axes[3] = {camera_frame(b.right), camera_frame(b.front), camera_frame(b.up)};
  for (int r = 0; r < 3; ++r)
    for (int k = 0; k < 3; ++k) b.rotation_camera[static_cast<std::size_t>(3 * r + k)] = axes[k][r];
  return b;
}

void grow(std::optional<PixelBox>& box, int x, int y) {
  if (!box) {
    box = PixelBox{x, y, x, y};
    return;
  }
  (*box)[0] = std::min((*box)[0], x);
  (*box)[1] = std::min((*box)[1], y);
  (*box)[2] = std::max((*box)[2], x);
  (*box)[3] = std::max((*box)[3], y);
}

// The centre of an object's bounding box in the scene frame.
Vec3 object_centre(const Scene& scene, const ObjectInstance& o) {
  const auto [lo, hi] = object_bounds(scene, o);
  return (lo + hi) * 0.5;
}

// The background ring of object `id`: pixels within `width` (Chebyshev) of one of its
// visible pixels that no object covers, found with a summed-area table of its pixels.
void measure_ring(const Film& film, std::uint32_t id, ObjectTruth& t) {
  const PixelBox& b = *t.bbox;
  const int w = t.ring_width;
  const int x0 = std::max(0, b[0] - w), y0 = std::max(0, b[1] - w);
  const int x1 = std::min(film.width() - 1, b[2] + w), y1 = std::min(film.height() - 1, b[3] + w);
  const int cols = x1 - x0 + 1, rows = y1 - y0 + 1;
  std::vector<std::uint32_t> sum(static_cast<std::size_t>(cols + 1) * (rows + 1), 0);
  const auto at = [&](int c, int r) -> std::uint32_t& {
    return sum[static_cast<std::size_t>(r) * (cols + 1) + c];
  };
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < cols; ++c)
      at(c + 1, r + 1) =
          (film.target(x0 + c, y0 + r) == id ? 1u : 0u) + at(c, r + 1) + at(c + 1, r) - at(c, r);
  double total = 0.0;
  std::uint64_t n = 0;
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < cols; ++c) {
      if (film.target(x0 + c, y0 + r) != 0) continue;
      const int ca = std::max(0, c - w), cb = std::min(cols, c + w + 1);
      const int ra = std::max(0, r - w), rb = std::min(rows, r + w + 1);
      if (at(cb, rb) - at(ca, rb) - at(cb, ra) + at(ca, ra) == 0) continue;
      total += film.luminance(x0 + c, y0 + r);
      ++n;
    }
  t.background_pixels = n;
  t.background_luminance = n > 0 ? total / static_cast<double>(n) : 0.0;
  if (n > 0 && t.background_luminance > 0.0)
    t.contrast = (t.luminance - t.background_luminance) / t.background_luminance;
}

// A set of pixels (indices y * width + x) as COCO's uncompressed RLE over a height x width
// image: column-major runs, starting with a run of zeros.
std::vector<std::uint32_t> rle_of(std::vector<std::uint64_t> pixels, int width, int height) {
  for (std::uint64_t& p : pixels)  // to column-major order
    p = (p % static_cast<std::uint64_t>(width)) * static_cast<std::uint64_t>(height) +
        p / static_cast<std::uint64_t>(width);
  std::sort(pixels.begin(), pixels.end());
  std::vector<std::uint32_t> counts;
  std::uint64_t at = 0;  // the next column-major index not yet counted
  for (std::size_t i = 0; i < pixels.size();) {
    std::size_t j = i + 1;
    while (j < pixels.size() && pixels[j] == pixels[j - 1] + 1) ++j;
    counts.push_back(static_cast<std::uint32_t>(pixels[i] - at));  // zeros before the run
    counts.push_back(static_cast<std::uint32_t>(j - i));
    at = pixels[j - 1] + 1;
    i = j;
  }
  const std::uint64_t total =
      static_cast<std::uint64_t>(width) * static_cast<std::uint64_t>(height);
  if (at < total || counts.empty()) counts.push_back(static_cast<std::uint32_t>(total - at));
  return counts;
}

}  // namespace

int ring_width(const PixelBox& box) {
  const int side = std::max(box[2] - box[0], box[3] - box[1]) + 1;
  return std::max(3, static_cast<int>(std::ceil(0.1 * side)));
}

std::vector<ObjectTruth> object_truth(const Scene& scene, const View& view, const Film& film,
                                      bool centre_first) {
  std::vector<ObjectTruth> out(scene.objects.size());
  if (out.empty()) return out;
  const Footprints footprint = footprints(scene, view, centre_first);
  std::vector<double> luminance(out.size(), 0.0);
  std::vector<std::vector<std::uint64_t>> footprint_pixels(out.size());
  for (int y = 0; y < film.height(); ++y)
    for (int x = 0; x < film.width(); ++x) {
      const std::uint32_t seen = film.target(x, y);
      if (seen > 0 && seen <= out.size()) {
        ObjectTruth& t = out[seen - 1];
        ++t.visible_pixels;
        t.visible_coverage += film.coverage(x, y);
        grow(t.bbox, x, y);
        luminance[seen - 1] += film.luminance(x, y);
      }
      for (const FootprintHit& f :
           footprint.pixels[static_cast<std::size_t>(y) * film.width() + x]) {
        ++out[f.object].footprint_pixels;
        out[f.object].footprint_coverage += f.share;
        footprint_pixels[f.object].push_back(static_cast<std::uint64_t>(y) * film.width() + x);
        grow(out[f.object].footprint_bbox, x, y);
      }
    }
  for (std::size_t i = 0; i < out.size(); ++i) {
    ObjectTruth& t = out[i];
    t.name = scene.objects[i].name;
    t.mesh = scene.object_prototypes[scene.objects[i].prototype].file;
    t.footprint_rle = rle_of(std::move(footprint_pixels[i]), film.width(), film.height());
    t.range = length(object_centre(scene, scene.objects[i]) - view.position);
    t.box = object_box(scene, scene.objects[i], view);
    if (const std::optional<double> beyond = footprint.beyond_the_frame[i]) {
      const double whole = t.footprint_coverage + *beyond;
      t.truncation = whole > 0.0 ? *beyond / whole : 0.0;
    }
    if (t.footprint_coverage > 0.0)
      t.visible_fraction = std::min(1.0, t.visible_coverage / t.footprint_coverage);
    if (t.visible_pixels == 0) continue;
    t.luminance = luminance[i] / static_cast<double>(t.visible_pixels);
    t.ring_width = ring_width(*t.bbox);
    measure_ring(film, static_cast<std::uint32_t>(i + 1), t);
  }
  return out;
}

}  // namespace landsim::renderer
