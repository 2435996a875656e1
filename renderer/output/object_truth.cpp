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

// Per pixel, the object (index + 1) the first sample's ray meets in a scene of the objects
// alone; 0 for none. The rays are the render's own (sample_ray, sample 0).
std::vector<std::uint32_t> footprints(const Scene& scene, const View& view, bool centre_first) {
  const EmbreeScene objects(scene, nullptr, EmbreeScene::Contents::objects_only);
  const Camera camera(view);
  std::vector<std::uint32_t> out(static_cast<std::size_t>(view.width) * view.height, 0);
  tbb::parallel_for(0, view.height, [&](int y) {
    for (int x = 0; x < view.width; ++x) {
      const auto pixel = static_cast<std::uint64_t>(y) * static_cast<std::uint64_t>(view.width) +
                         static_cast<std::uint64_t>(x);
      const CounterRng rng(scene.settings.seed, pixel, 0);
      const std::optional<Ray> ray = sample_ray(camera, rng, x, y, centre_first);
      if (!ray) continue;
      const auto hit = objects.intersect(*ray, 0.0f, std::numeric_limits<float>::infinity());
      if (hit && hit->object_index >= 0)
        out[static_cast<std::size_t>(pixel)] = static_cast<std::uint32_t>(hit->object_index + 1);
    }
  });
  return out;
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
  const ObjectPrototype& p = scene.object_prototypes[o.prototype];
  Vec3 lo{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
          std::numeric_limits<double>::infinity()};
  Vec3 hi = -lo;
  for (const Vec3f& v : p.vertices) {
    const Vec3 w = o.apply(v);
    lo = {std::min(lo.x, w.x), std::min(lo.y, w.y), std::min(lo.z, w.z)};
    hi = {std::max(hi.x, w.x), std::max(hi.y, w.y), std::max(hi.z, w.z)};
  }
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

}  // namespace

int ring_width(const PixelBox& box) {
  const int side = std::max(box[2] - box[0], box[3] - box[1]) + 1;
  return std::max(3, static_cast<int>(std::ceil(0.1 * side)));
}

std::vector<ObjectTruth> object_truth(const Scene& scene, const View& view, const Film& film,
                                      bool centre_first) {
  std::vector<ObjectTruth> out(scene.objects.size());
  if (out.empty()) return out;
  const std::vector<std::uint32_t> footprint = footprints(scene, view, centre_first);
  std::vector<double> luminance(out.size(), 0.0);
  for (int y = 0; y < film.height(); ++y)
    for (int x = 0; x < film.width(); ++x) {
      const std::uint32_t seen = film.target(x, y);
      if (seen > 0 && seen <= out.size()) {
        ObjectTruth& t = out[seen - 1];
        ++t.visible_pixels;
        grow(t.bbox, x, y);
        luminance[seen - 1] += film.luminance(x, y);
      }
      const std::uint32_t f = footprint[static_cast<std::size_t>(y) * film.width() + x];
      if (f > 0) {
        ++out[f - 1].footprint_pixels;
        grow(out[f - 1].footprint_bbox, x, y);
      }
    }
  for (std::size_t i = 0; i < out.size(); ++i) {
    ObjectTruth& t = out[i];
    t.name = scene.objects[i].name;
    t.range = length(object_centre(scene, scene.objects[i]) - view.position);
    if (t.footprint_pixels > 0)
      t.visible_fraction =
          static_cast<double>(t.visible_pixels) / static_cast<double>(t.footprint_pixels);
    if (t.visible_pixels == 0) continue;
    t.luminance = luminance[i] / static_cast<double>(t.visible_pixels);
    t.ring_width = ring_width(*t.bbox);
    measure_ring(film, static_cast<std::uint32_t>(i + 1), t);
  }
  return out;
}

}  // namespace landsim::renderer
