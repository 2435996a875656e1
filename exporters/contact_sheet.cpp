#include "exporters/contact_sheet.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "renderer/output/image_output.h"
#include "renderer/scene.h"
#include "renderer/transport/render.h"
#include "trees/mesher.h"

namespace landsim::exporters {
namespace {

// A flat square of ground under the tree (its northern half for a cutaway).
terrain::GroundMesh ground_square(float half, bool cutaway) {
  terrain::GroundMesh m;
  const float south = cutaway ? 0.0f : -half;
  m.vertices = {{-half, south, 0}, {half, south, 0}, {half, half, 0}, {-half, half, 0}};
  m.normals.assign(4, Vec3f{0, 0, 1});
  m.indices = {0, 1, 2, 0, 2, 3};
  return m;
}

// The tree alone, seen from the south-west, the whole of its bounds in view; tile k of
// the sheet.
renderer::Scene tile_scene(const trees::TreeGeometry& tree, const ContactSheetOptions& o,
                           std::size_t k, renderer::View& view) {
  const auto [lo, hi] = tree.bounds();
  const float size = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z, 1.0f});
  renderer::Scene s = studio_scene(20.0f * size);
  renderer::TreePrototype proto;
  proto.geometry = tree;
  proto.dress(tree.colours);
  s.prototypes.push_back(std::move(proto));
  s.instances.push_back({0, {0, 0, 0}, 0.0, 1.0});
  s.settings.spp = o.spp;
  s.settings.seed = o.seed;
  const Vec3 centre{0.5 * (lo.x + hi.x), 0.5 * (lo.y + hi.y), 0.5 * (lo.z + hi.z)};
  const double fov = 40.0;
  const double distance = 0.75 * size / std::tan(0.5 * fov * std::numbers::pi / 180.0);
  const Vec3 from = normalize(Vec3{-0.6, -1.0, 0.25});
  view = {"tile", centre + from * distance, centre, fov, o.tile, o.tile};
  s.settings.degradation = k < o.detail_r2.size();
  if (s.settings.degradation) {
    s.prototypes[0].degradation = o.factors;
    // The renderer measures range to the middle of the tree's height above its base.
    const Vec3 middle{0.0, 0.0, 0.5 * (lo.z + hi.z)};
    view.detail_range_scale =
        o.detail_r2[k] /
        trees::calibrated_range(length(view.position - middle), view.height, view.fov_y_deg);
  }
  return s;
}

}  // namespace

renderer::Scene studio_scene(float half, bool cutaway) {
  renderer::Scene s;
  s.ground.mesh = ground_square(half, cutaway);
  s.ground.plain = !cutaway;  // the cut opens onto the space under the ground
  s.sun.direction = normalize(Vec3{-0.5, -0.6, 0.8});
  return s;
}

renderer::TreePrototype person_figure() {
  trees::TreeSkeleton figure;
  trees::StemSkeleton body;  // legs and trunk, then shoulders narrowing to the neck
  const auto add = [&](trees::StemSkeleton& stem, double z, double r) {
    stem.sections.push_back({{0, 0, z}, {0, 0, 1}, {1, 0, 0}, r});
  };
  add(body, 0.0, 0.12), add(body, 0.85, 0.16), add(body, 1.35, 0.2), add(body, 1.45, 0.14),
      add(body, 1.52, 0.05);
  trees::StemSkeleton head;
  for (int k = 0; k <= 6; ++k) {
    const double a = std::numbers::pi * k / 6.0;
    add(head, 1.52 + 0.115 * (1.0 - std::cos(a)), 0.1 * std::sin(a));
  }
  figure.stems = {body, head};
  renderer::TreePrototype person;
  person.geometry = trees::mesh_tree(figure, trees::MeshResolution{{12, 12, 12, 12}});
  person.bark_albedo = {0.35f, 0.12f, 0.10f};
  return person;
}

renderer::Film render_contact_sheet(const std::vector<trees::TreeGeometry>& trees,
                                    const ContactSheetOptions& o) {
  const int columns = std::max(1, std::min(o.columns, static_cast<int>(trees.size())));
  const int rows = (static_cast<int>(trees.size()) + columns - 1) / columns;
  renderer::Film sheet(columns * o.tile, std::max(rows, 1) * o.tile);
  for (std::size_t k = 0; k < trees.size(); ++k) {
    renderer::View view;
    const renderer::Scene scene = tile_scene(trees[k], o, k, view);
    const renderer::Film tile = renderer::Renderer(scene).render(view, {});
    const int x0 = static_cast<int>(k) % columns * o.tile;
    const int y0 = static_cast<int>(k) / columns * o.tile;
    for (int y = 0; y < o.tile; ++y)
      for (int x = 0; x < o.tile; ++x) sheet.set(x0 + x, y0 + y, tile.rgb(x, y), {});
  }
  return sheet;
}

renderer::Film render_plate(const trees::TreeGeometry& tree, const std::vector<double>& ranges,
                            ContactSheetOptions options) {
  options.columns = static_cast<int>(ranges.size());
  options.detail_r2 = ranges;  // the paper's calibration: r2 is the range
  return render_contact_sheet(std::vector<trees::TreeGeometry>(ranges.size(), tree), options);
}

void write_labelled_png(const renderer::Film& sheet, const std::vector<std::string>& labels,
                        const ContactSheetOptions& o, const std::filesystem::path& path) {
  const int columns = std::max(1, o.columns);
  std::vector<renderer::ImageLabel> placed;
  for (std::size_t k = 0; k < labels.size(); ++k)
    placed.push_back({static_cast<int>(k) % columns * o.tile + 8,
                      static_cast<int>(k) / columns * o.tile + 24, labels[k]});
  renderer::write_preview_png(sheet, path, std::nullopt, placed);
}

}  // namespace landsim::exporters
