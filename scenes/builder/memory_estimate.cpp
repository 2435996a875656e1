#include "scenes/builder/memory_estimate.h"
#include "scenes/scenario/randomise.h"

#include "renderer/camera.h"

#include "scenes/builder/detail/scene_objects.h"

#include <fmt/format.h>
#include <tbb/parallel_for.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <optional>
#include <set>

#include "core/input_error.h"
#include "core/process_memory.h"
#include "featuremaps/placement.h"
#include "renderer/acceleration/level_ladder.h"
#include "renderer/acceleration/memory_model.h"
#include "renderer/materials/grass_patch.h"
#include "renderer/output/atmosphere_layers.h"
#include "renderer/output/illumination_layers.h"
#include "renderer/output/image_io.h"
#include "scenes/builder/detail/camera_check.h"
#include "scenes/builder/detail/context_terrain.h"
#include "scenes/builder/detail/grass_cover.h"
#include "scenes/builder/detail/scene_foundation.h"
#include "scenes/builder/detail/tree_variant.h"
#include "scenes/builder/detail/vegetation_input.h"
#include "scenes/builder/scene_builder.h"
#include "terrain/context_mesh.h"
#include "terrain/dem_loader.h"
#include "trees/degradation.h"

namespace landsim::scenes {
namespace {

namespace mm = renderer::memory;

template <typename T>
double bytes_of(const std::vector<T>& v) {
  return static_cast<double>(v.capacity() * sizeof(T));
}

// One generated variant: our arrays' bytes and its primitives by kind.
struct VariantSize {
  double bytes = 0.0;
  double triangles = 0.0, segments = 0.0, discs = 0.0;
};

VariantSize variant_size(const trees::TreeGeometry& g) {
  VariantSize v;
  for (const trees::GroupGeometry& group : g.groups) {
    v.bytes += bytes_of(group.triangles.vertices) + bytes_of(group.triangles.normals) +
               bytes_of(group.triangles.uvs) + bytes_of(group.triangles.indices) +
               bytes_of(group.lines.points) + bytes_of(group.lines.radii) +
               bytes_of(group.lines.first) + bytes_of(group.points.centres) +
               bytes_of(group.points.radii) + bytes_of(group.points.normals) +
               bytes_of(group.item_triangle_end) + bytes_of(group.item_line_end) +
               bytes_of(group.item_point_end) + bytes_of(group.item_vigour);
    v.triangles += static_cast<double>(group.triangles.triangle_count());
    v.segments += static_cast<double>(group.lines.segment_count());
    v.discs += static_cast<double>(group.points.point_count());
  }
  return v;
}

// The ground mesh: one vertex per valid cell, two triangles per quad of four valid corners
// (the odd three-corner triangle is not worth counting).
struct GroundSize {
  double cells = 0.0, vertices = 0.0, triangles = 0.0;
};

// With context grids or detail: the quadtree's cells (counted, not built), two triangles each and a
// few more where a neighbour is finer (kContextTrianglesPerCell, measured on the Kagwene example
// with a 100 km context: 2.004), about one vertex each; the context grids and blend offsets
// while the scene is built.
constexpr double kContextTrianglesPerCell = 2.0;

GroundSize context_ground_size(const Scenario& s, const terrain::ElevationGrid& grid,
                               const std::vector<renderer::View>& views) {
  const terrain::TerrainField field = detail::context_terrain(s, grid);
  terrain::ContextMeshOptions options = context_mesh_options(views, grid.min_height());
  // The quadtree's shape does not depend on the relief's amplitudes: a flat one counts it.
  const auto samples =
      static_cast<std::size_t>(grid.cols()) * static_cast<std::size_t>(grid.rows());
  std::optional<terrain::SurfaceDetail> flat;
  if (s.ground.detail)
    flat.emplace(grid, std::vector<float>(samples), std::vector<float>(samples), 0);
  options.detail = flat ? &*flat : nullptr;
  const auto cells = static_cast<double>(terrain::count_context_cells(field, options));
  return {field.stored_cells(), cells, cells * kContextTrianglesPerCell};
}

GroundSize ground_size(const Scenario& s, const terrain::ElevationGrid& grid,
                       const std::vector<renderer::View>& views) {
  if (!s.terrain.context.empty() || s.ground.detail) return context_ground_size(s, grid, views);
  GroundSize g;
  g.cells = static_cast<double>(grid.cols()) * grid.rows();
  g.vertices = g.cells - static_cast<double>(grid.nodata_count());
  for (int r = 0; r + 1 < grid.rows(); ++r)
    for (int c = 0; c + 1 < grid.cols(); ++c)
      if (grid.valid(c, r) && grid.valid(c + 1, r) && grid.valid(c, r + 1) &&
          grid.valid(c + 1, r + 1))
        g.triangles += 2.0;
  return g;
}

// Where each species stands: its feature-map area (m^2, cells selecting its bit over
// terrain) and, per view, the distance from the camera to its nearest cell.
struct SpeciesExtent {
  double area = 0.0;
  std::vector<double> nearest, farthest;  // per view, metres
};

std::vector<SpeciesExtent> species_extents(const Scenario& s,
                                           const std::vector<renderer::View>& views,
                                           const featuremaps::VegetationMap& map,
                                           const terrain::ElevationGrid& grid) {
  std::vector<SpeciesExtent> extent(s.species.size());
  for (SpeciesExtent& e : extent) {
    e.nearest.assign(views.size(), 1e300);
    e.farthest.assign(views.size(), 0.0);
  }
  const terrain::GeoTransform& t = map.transform();
  const double cell_area = t.cell_size_x * t.cell_size_y;
  const double half_diagonal = 0.5 * std::hypot(t.cell_size_x, t.cell_size_y);
  for (int r = 0; r < map.rows(); ++r)
    for (int c = 0; c < map.cols(); ++c) {
      const featuremaps::VegetationCell cell = map.at(c, r);
      if (cell.tree_bits() == 0) continue;
      const double x = t.origin_x + (c + 0.5) * t.cell_size_x;
      const double y = t.origin_y - (r + 0.5) * t.cell_size_y;
      const std::optional<double> z = grid.height(x, y);
      if (!z) continue;
      for (std::size_t k = 0; k < s.species.size(); ++k) {
        if (!cell.has_tree_bit(s.species[k].bit)) continue;
        extent[k].area += cell_area;
        for (std::size_t v = 0; v < views.size(); ++v) {
          const double d = length(Vec3{x, y, *z} - views[v].position);
          extent[k].nearest[v] = std::min(extent[k].nearest[v], std::max(d - half_diagonal, 1.0));
          extent[k].farthest[v] = std::max(extent[k].farthest[v], d + half_diagonal);
        }
      }
    }
  return extent;
}

// Primitives Embree holds for one level of a variant: its BVH over what the level draws
// of the shared buffers (renderer/acceleration/level_ladder.h drawn_group).
double embree_level_bytes(const renderer::TreePrototype& p, const trees::TreeDetail& detail) {
  double bytes = 0.0;
  for (int g = 0; g < trees::kGroupCount; ++g) {
    const auto group = static_cast<trees::Group>(g);
    const renderer::DrawnGroup n = renderer::drawn_group(
        p.geometry.group(group), group, detail.groups[static_cast<std::size_t>(g)]);
    bytes += n.triangles * mm::kEmbreeTreeTriangle;
    bytes += static_cast<double>(n.far_end - n.far_first) *
             (group == trees::Group::leaves ? mm::kEmbreeDisc : mm::kEmbreeCurveSegment);
  }
  return bytes;
}

// A view's levels of a variant whose trees stand from `nearest` to `farthest` metres from
// it: every level the Embree scene builds for ranges between (Weber & Penn section 5's
// detail at each anchor step of the ladder), or full detail without degradation. At fine
// pixels the near steps keep nearly every primitive, so several near-full levels add up.
double view_levels_bytes(const renderer::TreePrototype& p, const renderer::View& view,
                         double nearest, double farthest, bool degrade) {
  if (!degrade) return embree_level_bytes(p, trees::full_detail(p.geometry));
  const auto r2 = [&](double d) {
    return view.detail_range_scale * renderer::calibrated_view_range(view, d);
  };
  double bytes = 0.0;
  for (const trees::TreeDetail& d : renderer::drawn_level_details(p, r2(nearest), r2(farthest)))
    bytes += embree_level_bytes(p, d);
  return bytes;
}

// Distinct variants among n trees each picking one of v at random (expected value).
double variants_in_use(double n, int v) { return v * (1.0 - std::pow(1.0 - 1.0 / v, n)); }

// Top-level entries per tree with range degradation: only trees at least
// kPerPixelBlendMinPixels tall on screen are drawn at two levels with complementary ray
// masks (renderer/acceleration/stochastic_lod.h); the rest take one. Measured on the calibration
// scenes (bench/memory.sh): 1.000 to 1.001 entries per tree.
constexpr double kEntriesPerDegradedTree = 1.0;
// Generating a variant holds its skeleton and the mesher's working arrays besides the
// geometry it returns (measured on the calibration scenes).
constexpr double kGenerationOverhead = 0.2;
// Placement holds every tree twice while rows are concatenated (PlacedTree, 48 bytes).
constexpr double kPlacementBytesPerTree = 2.0 * sizeof(featuremaps::PlacedTree);

struct Parts {
  double scene_variants = 0.0, scene_instances = 0.0, scene_ground = 0.0, scene_grass = 0.0;
  double build_extra = 0.0;  // grid, map, placement and generation while the scene is built
  double view_instances = 0.0, view_ground = 0.0;
  // The largest view's (views are rendered one after the other).
  double view_prototypes = 0.0, view_grass = 0.0, view_film = 0.0;
};

std::string mb(double bytes) { return fmt::format("{:.0f} MB", bytes / 1e6); }

}  // namespace

std::size_t MemoryEstimate::total_bytes() const {
  std::size_t total = program_bytes;
  for (const MemoryPart& p : parts) total += p.bytes;
  return total;
}

// A texture as the scene holds it (renderer/materials/texture_image: linear RGB floats), from its
// header alone; zero when the header cannot be read (the build reports why). The module's
// buffers while it is read are gone before the trees are built (measured: a 4096 x 4096
// texture added 205 MB to the peak, its RGB floats' 201 MB).
double texture_bytes(const std::string& path) {
  int width = 0, height = 0, channels = 0;
  std::string error;
  if (!renderer::image_io().probe(path, width, height, channels, error)) return 0.0;
  return static_cast<double>(width) * height * 3.0 * sizeof(float);
}

// The [[objects]] meshes as the render holds them: each file's prototype (positions,
// normals, texture coordinates, indices, materials), its base-colour textures and its Embree
// scene, twice (the render's and the objects-only scene of the truth pass). Reads each file once,
// handing it on in `keep` when given.
double object_bytes(const Scenario& s, VariantCache* keep) {
  std::map<std::string, MeshData> local;
  std::map<std::string, MeshData>& meshes = keep != nullptr ? keep->meshes : local;
  double bytes = 0.0;
  std::set<std::string> counted;
  for (const ObjectSettings& o : s.objects) {
    const MeshData& mesh = detail::read_object_mesh(o, meshes);
    if (!counted.insert(o.file).second) continue;
    const double vertices = static_cast<double>(mesh.positions.size() / 3);
    const double triangles = static_cast<double>(mesh.indices.size() / 3);
    const double per_vertex = mesh.uvs.empty() ? 24.0 : 32.0;
    bytes += vertices * per_vertex + triangles * 16.0 +
             2.0 * (vertices * per_vertex + triangles * mm::kEmbreeGridTriangle);
    for (const MeshMaterial& m : mesh.materials)
      if (!m.texture.empty() && counted.insert(m.texture).second) bytes += texture_bytes(m.texture);
  }
  return bytes + static_cast<double>(s.objects.size()) * 2.0 * mm::kEmbreeInstance;
}

// The [[canopy]] clouds (docs/CANOPIES.md): every variant's discs stored once, in the scenario
// (those read from a file), in the prototype (centre, radius, normal, item end) and in Embree
// (an oriented disc point), and every copy's instance with its top-level record.
double canopy_bytes(const Scenario& s) {
  constexpr double kSettingsDisc = sizeof(LeafDisc);
  constexpr double kPrototypeDisc = 3 * 4 + 4 + 3 * 4 + 4;
  double bytes = 0.0;
  for (const CanopySettings& c : s.canopies) {
    const double discs = c.generated ? static_cast<double>(c.generated->discs) *
                                           static_cast<double>(c.generated->variants)
                                     : static_cast<double>(c.discs.size());
    bytes += discs * (kPrototypeDisc + mm::kEmbreeDisc) +
             static_cast<double>(c.discs.size()) * kSettingsDisc +
             static_cast<double>(c.positions.size()) * (mm::kEmbreeInstance + mm::kTopLevelRecord);
  }
  return bytes;
}

// A film pixel with its bands, the sensor's channels and the layers derived when writing
// (reflectance: RGB, bands and channels), and the sensor's work on a view: each channel's
// plane through the optics and its digital numbers, and one FFT's two complex buffers (with
// their margins) at a time.
static double film_pixel_bytes(const Scenario& s) {
  const double bands = static_cast<double>(s.bands.size());
  const double channels = s.sensor ? static_cast<double>(s.sensor->model.channels.size()) : 0.0;
  const double reflectance = s.render.reflectance ? 3.0 + bands + channels : 0.0;
  // The atmosphere's five parts and the surface's reflectance factor, each RGB and every layer.
  const double atmosphere = s.render.atmosphere_layers
                                ? (renderer::kAtmosphereParts + 1.0) * (3.0 + bands + channels)
                                : 0.0;
  const double illumination = s.render.illumination_layers ? renderer::kIlluminationLayers : 0.0;
  const double sensor = channels > 0.0 ? channels * (4.0 + 2.0) + 2.0 * 8.0 * 1.2 : 0.0;
  return mm::kFilmPixel +
         mm::kFilmBandPixel * (bands + channels + reflectance + atmosphere + illumination) + sensor;
}

MemoryEstimate estimate_memory(const Scenario& s, VariantCache* keep,
                               std::optional<std::size_t> program) {
  MemoryEstimate e;
  e.scenario = s.source;
  // The program as the render will have it: with its image module (loaded by render before
  // this estimate; counted, not loaded, by info).
  e.program_bytes = program ? *program
                            : resident_bytes() + (renderer::image_io_loaded()
                                                      ? std::size_t{0}
                                                      : static_cast<std::size_t>(mm::kImageModule));
  // The build's own first stages: the grid, the ground rasters and the vegetation map.
  const detail::SceneFoundation foundation = detail::lay_foundation(s);
  const terrain::ElevationGrid& grid = foundation.grid;
  detail::warn_cameras_below_ground(s, foundation.views, grid);
  const Vec3 origin = grid.centre();
  const GroundSize ground = ground_size(s, grid, foundation.views);
  Parts p;
  p.scene_ground = ground.vertices * 24.0 + ground.triangles * (12.0 + 1.0);
  p.view_ground = ground.triangles * mm::kEmbreeGridTriangle;
  // The grid (or the context grids) as the ground counts it, plus the rasters and the map.
  p.build_extra = ground.cells * 4.0 + foundation.bytes() -
                  static_cast<double>(grid.cols()) * grid.rows() * sizeof(float);
  e.triangles_stored = e.triangles_instanced = ground.triangles;

  const std::optional<featuremaps::VegetationMap>& map = foundation.map;
  renderer::GrassCover cover;
  std::vector<SpeciesExtent> extent(s.species.size());
  std::vector<double> trees(s.species.size(), 0.0);
  if (map) {
    extent = species_extents(s, foundation.views, *map, grid);
    for (std::size_t k = 0; k < s.species.size(); ++k) {
      trees[k] = extent[k].area * s.species[k].density_per_ha / 1e4;
      e.instances += trees[k];
      e.instances_per_species[s.species[k].species.name] += trees[k];
    }
    if (!s.grass.empty())
      cover = detail::grass_cover(
          s, *map, grid, origin, [&](double x, double y) { return foundation.blocks_grass(x, y); });
  }
  // One variant per species stands for all of its variants.
  std::vector<std::optional<renderer::TreePrototype>> variant(s.species.size());
  tbb::parallel_for(std::size_t{0}, s.species.size(), [&](std::size_t k) {
    if (trees[k] >= 0.5)
      variant[k] =
          detail::make_tree_variant(s, static_cast<std::uint32_t>(k), 0, s.render.frames.front());
  });
  const bool degrade = s.render.degradation;
  const std::vector<renderer::View> views = foundation.views_around(origin);
  std::vector<double> view_prototypes(views.size(), 0.0);
  for (std::size_t k = 0; k < s.species.size(); ++k) {
    if (!variant[k]) continue;
    const VariantSize size = variant_size(variant[k]->geometry);
    // With wind each variant is drawn once per phase group its trees fall in.
    const int groups = s.wind.active() ? s.wind.phase_groups : 1;
    const double used = variants_in_use(trees[k], s.species[k].variants * groups);
    e.unique_variants += static_cast<std::size_t>(std::ceil(used - 1e-9));
    p.scene_variants += used * size.bytes;
    e.triangles_stored += used * size.triangles;
    e.triangles_instanced += trees[k] * size.triangles;
    for (std::size_t v = 0; v < views.size(); ++v)
      view_prototypes[v] += used * view_levels_bytes(*variant[k], views[v], extent[k].nearest[v],
                                                     extent[k].farthest[v], degrade);
  }
  p.build_extra += kGenerationOverhead * p.scene_variants;
  p.scene_instances = e.instances * sizeof(renderer::TreeInstance);
  p.build_extra += e.instances * kPlacementBytesPerTree;
  p.view_instances =
      e.instances * kEntriesPerDegradedTree * (mm::kEmbreeInstance + mm::kTopLevelRecord);
  // Per tile its type, height and normal; per map cell the grass mask's type.
  p.scene_grass = static_cast<double>(cover.type.size()) * (1.0 + 4.0 + 12.0) +
                  static_cast<double>(cover.mask.type.size());
  for (std::uint8_t t : cover.type) e.grass_tiles += t != 0 ? 1 : 0;
  // Views are rendered one after the other: the largest sets the peak.
  double largest_view = -1.0;
  for (std::size_t v = 0; v < views.size(); ++v) {
    std::size_t patches = 0;
    if (cover.cols > 0)
      renderer::for_each_grass_patch(cover, views[v], degrade,
                                     [&](const renderer::GrassPatchPlacement&) { ++patches; });
    e.grass_patches_drawn = std::max(e.grass_patches_drawn, patches);
    // Each drawn patch: its Embree instance, top-level record and frame (the blade filter's).
    const double grass =
        static_cast<double>(patches) * (mm::kEmbreeInstance + mm::kTopLevelRecord + 48.0);
    const double film = static_cast<double>(views[v].width) * views[v].height * film_pixel_bytes(s);
    if (view_prototypes[v] + grass + film > largest_view) {
      largest_view = view_prototypes[v] + grass + film;
      p.view_prototypes = view_prototypes[v];
      p.view_grass = grass;
      p.view_film = film;
    }
  }

  const auto part = [&](const std::string& id, const std::string& name, double bytes,
                        const std::string& remedy) {
    if (bytes >= 1.0) e.parts.push_back({id, name, static_cast<std::size_t>(bytes), remedy});
  };
  if (keep != nullptr)
    for (std::size_t k = 0; k < s.species.size(); ++k)
      if (variant[k])
        keep->trees.insert_or_assign({static_cast<std::uint32_t>(k), 0, s.render.frames.front()},
                                     std::move(*variant[k]));
  part("tree_variants", "tree variants", p.scene_variants + p.view_prototypes,
       degrade ? "fewer variants per species, or a lower [render] quality"
               : "[render] degradation = true (far trees drawn with fewer primitives), or "
                 "fewer variants per species");
  part("tree_instances", fmt::format("tree instances ({:.0f} trees)", e.instances),
       p.scene_instances + p.view_instances, "a lower density_per_ha, or a smaller feature map");
  part("ground", "ground", p.scene_ground + p.view_ground, "a coarser elevation grid");
  part("grass", "grass", p.scene_grass + p.view_grass,
       "fewer [[grass]] types, or grass on less of the map");
  part("image", "image", p.view_film, "a smaller --width/--height");
  part("canopies", "leaf clouds ([[canopy]])", canopy_bytes(s),
       "fewer discs or variants per [[canopy]], or fewer copies");
  part("objects", "scene objects", object_bytes(s, keep),
       "[[objects]] meshes of fewer triangles, or smaller textures");
  // Objects are placed on the drawn ground through a BVH of its own
  // (renderer/acceleration/ground_probe).
  if (!s.objects.empty())
    part("ground_probe", "the ground probe placing objects",
         ground.triangles * mm::kEmbreeGridTriangle + ground.vertices * 12.0,
         "a coarser elevation grid");
  double textures = 0.0;
  for (const std::string& file : s.ground.texture_files)
    if (!file.empty()) textures += texture_bytes(file);
  for (const SpeciesSettings& entry : s.species)
    if (!entry.bark_texture.empty()) textures += texture_bytes(entry.bark_texture);
  part("textures", "ground and bark textures", textures, "smaller texture images");
  // Building the scene holds the terrain grid, the map and the placed trees besides; the
  // peak is whichever phase is larger.
  const double view_total =
      p.view_prototypes + p.view_instances + p.view_ground + p.view_grass + p.view_film;
  if (p.build_extra > view_total)
    part("scene_building", "scene building (grid, map, placement)", p.build_extra - view_total,
         "a smaller elevation grid or feature map, or fewer trees");
  std::sort(e.parts.begin(), e.parts.end(),
            [](const MemoryPart& a, const MemoryPart& b) { return a.bytes > b.bytes; });
  return e;
}

MemoryBudget default_memory_budget(int ranks_on_node) {
  std::size_t available = physical_memory_bytes();
  std::string what = "this machine's memory";
  if (const std::optional<std::size_t> limit = address_space_limit(); limit && *limit < available) {
    available = *limit;
    what = "the address-space limit (ulimit -v)";
  }
  const int ranks = std::max(1, ranks_on_node);
  MemoryBudget budget;
  budget.bytes = static_cast<std::size_t>(0.8 * static_cast<double>(available)) /
                 static_cast<std::size_t>(ranks);
  budget.source = ranks > 1 ? fmt::format("80% of {} shared by {} ranks", what, ranks)
                            : fmt::format("80% of {}", what);
  return budget;
}

void check_memory_budget(const MemoryEstimate& estimate, std::size_t budget_bytes,
                         const std::string& budget_source) {
  const std::size_t total = estimate.total_bytes();
  if (total <= budget_bytes) return;
  std::string largest;
  for (std::size_t i = 0; i < std::min<std::size_t>(3, estimate.parts.size()); ++i) {
    const MemoryPart& part = estimate.parts[i];
    largest += fmt::format("\n  {} {} (smaller with {})", mb(static_cast<double>(part.bytes)),
                           part.name, part.remedy);
  }
  throw InputError(fmt::format(
      "{}: the scene needs an estimated {} but {} allows {}; the largest parts:{}\nnothing was "
      "rendered (the estimate: `landsim info`; docs/PERFORMANCE.md \"Memory budget\")",
      estimate.scenario, mb(static_cast<double>(total)), budget_source,
      mb(static_cast<double>(budget_bytes)), largest));
}

nlohmann::json estimate_json(const Scenario& scenario, const MemoryEstimate& e) {
  const auto count = [](double n) { return static_cast<std::size_t>(std::llround(n)); };
  nlohmann::json per_species = nlohmann::json::object();
  std::size_t instances = 0;  // the sum of the species' rounded counts
  for (const auto& [name, n] : e.instances_per_species) {
    per_species[name] = count(n);
    instances += count(n);
  }
  nlohmann::json parts = nlohmann::json::object();
  for (const MemoryPart& p : e.parts) parts[p.id] = p.bytes;
  parts["program"] = e.program_bytes;
  return {{"instances", instances},
          {"instances_per_species", per_species},
          {"unique_variants", e.unique_variants},
          {"triangles_stored", count(e.triangles_stored)},
          {"triangles_instanced", count(e.triangles_instanced)},
          {"grass_tiles", e.grass_tiles},
          {"grass_patches_drawn", e.grass_patches_drawn},
          {"memory_estimate_bytes", e.total_bytes()},
          {"memory_parts_bytes", parts},
          // The image set: what a job array needs to size itself.
          {"views", scenario.views.size()},
          {"frames", scenario.render.frames.size()},
          {"randomised_images", randomised_images(scenario)},
          {"images",
           randomised_images(scenario) * scenario.views.size() * scenario.render.frames.size()}};
}

}  // namespace landsim::scenes
