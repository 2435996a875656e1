#include "scenes/builder/detail/leaf_cloud.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/counter_rng.h"
#include "core/input_error.h"
#include "renderer/spectra/spectrum.h"

namespace landsim::scenes::detail {
namespace {

constexpr double kPi = std::numbers::pi;
// Sides of a trunk's cylinder: the round trunk's area within 1% (a 32-gon's perimeter).
constexpr int kTrunkSides = 32;

// Whether `p` (relative to the cloud's origin) lies inside the shape.
bool inside(const GeneratedCloud& g, const Vec3& p) {
  const Vec3& s = g.size;
  switch (g.shape) {
    case CloudShape::sphere:
    case CloudShape::ellipsoid:
      return (p.x / s.x) * (p.x / s.x) + (p.y / s.y) * (p.y / s.y) + (p.z / s.z) * (p.z / s.z) <=
             1.0;
    case CloudShape::cylinder:
      return p.x * p.x + p.y * p.y <= s.x * s.x;
    case CloudShape::cone: {
      const double r = s.x * (1.0 - p.z / s.z);
      return p.x * p.x + p.y * p.y <= r * r;
    }
    case CloudShape::box:
      return true;
  }
  return false;
}

// The box the shape fills: [lo, hi].
std::array<Vec3, 2> box_of(const GeneratedCloud& g) {
  const Vec3& s = g.size;
  switch (g.shape) {
    case CloudShape::sphere:
    case CloudShape::ellipsoid:
      return {Vec3{-s.x, -s.y, -s.z}, s};
    case CloudShape::cylinder:
    case CloudShape::cone:
      return {Vec3{-s.x, -s.x, 0.0}, Vec3{s.x, s.x, s.z}};
    case CloudShape::box:
      return {Vec3{-0.5 * s.x, -0.5 * s.y, 0.0}, Vec3{0.5 * s.x, 0.5 * s.y, s.z}};
  }
  return {};
}

// de Wit's density of leaf inclination theta in [0, pi/2] (RAMI's definitions).
double inclination_density(LeafAngles a, double theta) {
  switch (a) {
    case LeafAngles::planophile:
      return 2.0 / kPi * (1.0 + std::cos(2.0 * theta));
    case LeafAngles::erectophile:
      return 2.0 / kPi * (1.0 - std::cos(2.0 * theta));
    case LeafAngles::plagiophile:
      return 2.0 / kPi * (1.0 - std::cos(4.0 * theta));
    case LeafAngles::extremophile:
      return 2.0 / kPi * (1.0 + std::cos(4.0 * theta));
    case LeafAngles::uniform:
      return std::sin(theta);
  }
  return 0.0;
}

// A leaf normal (upper hemisphere) drawn from `a`, by rejection under the densities' bound.
Vec3f draw_normal(LeafAngles a, CounterRng& rng) {
  double theta = 0.0;
  if (a == LeafAngles::uniform) {
    theta = std::acos(1.0 - rng.next());  // cos theta uniform: uniform over the hemisphere
  } else {
    do {
      theta = 0.5 * kPi * rng.next();
    } while (rng.next() * 4.0 / kPi > inclination_density(a, theta));
  }
  const double phi = 2.0 * kPi * rng.next();
  return Vec3f(
      Vec3{std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)});
}

// The leaf group of `discs` lifted by `lift`: every disc an item, drawn as itself.
trees::GroupGeometry leaf_group(const std::vector<LeafDisc>& discs, float lift) {
  trees::GroupGeometry g;
  g.mass_size = trees::kLeafMassSize;
  g.item_count = discs.size();
  for (std::size_t i = 0; i < discs.size(); ++i) {
    g.points.centres.push_back(discs[i].centre + Vec3f{0.0f, 0.0f, lift});
    g.points.radii.push_back(discs[i].radius);
    g.points.normals.push_back(discs[i].normal);
    g.item_point_end.push_back(static_cast<std::uint32_t>(i + 1));
  }
  return g;
}

// A trunk: an open cylinder of kTrunkSides quads from the ground to `t.height`, one item.
trees::GroupGeometry trunk_group(const CanopyTrunk& t) {
  trees::GroupGeometry g;
  g.item_count = 1;
  const auto r = static_cast<float>(t.radius), h = static_cast<float>(t.height);
  for (int k = 0; k < kTrunkSides; ++k) {
    const double a = 2.0 * kPi * k / kTrunkSides;
    const Vec3f n{static_cast<float>(std::cos(a)), static_cast<float>(std::sin(a)), 0.0f};
    g.triangles.vertices.push_back(n * r);
    g.triangles.vertices.push_back(n * r + Vec3f{0.0f, 0.0f, h});
    g.triangles.normals.push_back(n);
    g.triangles.normals.push_back(n);
  }
  for (std::uint32_t k = 0; k < kTrunkSides; ++k) {
    const std::uint32_t a = 2 * k, b = 2 * ((k + 1) % kTrunkSides);
    for (std::uint32_t i : {a, b, a + 1, b, b + 1, a + 1}) g.triangles.indices.push_back(i);
  }
  g.item_triangle_end = {static_cast<std::uint32_t>(g.triangles.triangle_count())};
  g.lines.points = {Vec3f{}, Vec3f{0.0f, 0.0f, h}};
  g.lines.radii = {r, r};
  g.lines.first = {0};
  g.item_line_end = {1};
  return g;
}

renderer::TreePrototype cloud_prototype(const CanopySettings& c, const std::vector<LeafDisc>& discs,
                                        std::uint16_t species) {
  renderer::TreePrototype p;
  p.leaf_discs = true;
  p.species = species;
  const float lift = c.trunk ? static_cast<float>(c.trunk->height) : 0.0f;
  p.geometry.group(trees::Group::leaves) = leaf_group(discs, lift);
  if (c.trunk) {
    p.geometry.group(trees::Group::trunk) = trunk_group(*c.trunk);
    const auto bark = static_cast<float>(c.trunk->reflectance);
    p.bark_albedo = {bark, bark, bark};
  }
  const auto r = static_cast<float>(c.reflectance), t = static_cast<float>(c.transmittance);
  p.leaf_reflectance = {r, r, r};
  p.leaf_transmittance = {t, t, t};
  // Monochromatic optics: every wavelength alike, as the benchmarks give them.
  auto optics = std::make_shared<renderer::SpectralOptics>();
  optics->reflectance = renderer::Spectrum::constant(r);
  optics->transmittance = renderer::Spectrum::constant(t);
  p.leaf_optics = std::move(optics);
  return p;
}

}  // namespace

std::vector<LeafDisc> generate_cloud(const GeneratedCloud& g, std::uint64_t seed,
                                     std::uint64_t canopy, std::uint64_t variant) {
  CounterRng rng(seed, hash_combine(0x6c656166636c6f75ull, canopy), variant);  // "leafclou"
  const auto [lo, hi] = box_of(g);
  std::vector<LeafDisc> discs;
  discs.reserve(static_cast<std::size_t>(g.discs));
  while (discs.size() < static_cast<std::size_t>(g.discs)) {
    const Vec3 p{lo.x + (hi.x - lo.x) * rng.next(), lo.y + (hi.y - lo.y) * rng.next(),
                 lo.z + (hi.z - lo.z) * rng.next()};
    if (!inside(g, p)) continue;
    discs.push_back({Vec3f(p), static_cast<float>(g.disc_radius), draw_normal(g.angles, rng)});
  }
  return discs;
}

namespace {

// How far a cloud's discs reach from its origin, metres.
double reach_of(const std::vector<LeafDisc>& discs) {
  double reach = 0.0;
  for (const LeafDisc& d : discs)
    reach = std::max(reach, static_cast<double>(length(d.centre)) + d.radius);
  return reach;
}

// Each copy must touch the terrain's extent: its origin within the cloud's reach of the grid's
// outer edges, and within 10 km (plus that reach) of its heights. A position a typing slip or
// a foreign coordinate system put kilometres away would otherwise render an empty image (or
// stretch the acceleration structure over 10^9 m).
void check_positions(const CanopySettings& c, const terrain::ElevationGrid& grid, double reach) {
  constexpr double kHeightSlack = 1e4;
  const terrain::GeoTransform& t = grid.transform();
  const double x0 = t.origin_x - reach, x1 = t.origin_x + grid.cols() * t.cell_size_x + reach;
  const double y0 = t.origin_y - grid.rows() * t.cell_size_y - reach, y1 = t.origin_y + reach;
  const double z0 = grid.min_height() - kHeightSlack - reach;
  const double z1 = grid.max_height() + kHeightSlack + reach;
  for (std::size_t i = 0; i < c.positions.size(); ++i) {
    const Vec3& p = c.positions[i];
    if (p.x >= x0 && p.x <= x1 && p.y >= y0 && p.y <= y1 && p.z >= z0 && p.z <= z1) continue;
    const std::string where = i < c.position_lines.size()
                                  ? c.positions_file + ":" + std::to_string(c.position_lines[i])
                                  : c.location;
    throw InputError(fmt::format(
        "{}: [canopy \"{}\"] positions: a copy at ({}, {}, {}) lies off the terrain (x {:.0f} "
        "to {:.0f}, y {:.0f} to {:.0f}, heights {:.0f} to {:.0f} m, the cloud's reach of {:.1f} m "
        "included): each copy's origin is in the elevation grid's coordinates",
        where, c.name, p.x, p.y, p.z, x0, x1, y0, y1, z0, z1, reach));
  }
}

}  // namespace

void add_canopies(const Scenario& s, const terrain::ElevationGrid& grid, renderer::Scene& scene) {
  for (std::size_t k = 0; k < s.canopies.size(); ++k) {
    const CanopySettings& c = s.canopies[k];
    const auto species = static_cast<std::uint16_t>(s.species.size() + k);
    const auto first = static_cast<std::uint32_t>(scene.prototypes.size());
    const int variants = c.generated ? c.generated->variants : 1;
    double reach = 0.0;
    for (int v = 0; v < variants; ++v) {
      const std::vector<LeafDisc> discs =
          c.generated ? generate_cloud(*c.generated, s.render.seed, k, v) : c.discs;
      reach = std::max(reach, reach_of(discs));
      scene.prototypes.push_back(cloud_prototype(c, discs, species));
    }
    if (c.trunk) reach = std::max(reach, std::hypot(c.trunk->radius, c.trunk->height));
    check_positions(c, grid, reach);
    for (std::size_t i = 0; i < c.positions.size(); ++i)
      scene.instances.push_back({first + static_cast<std::uint32_t>(i % variants),
                                 c.positions[i] - scene.origin, 0.0, 1.0});
  }
}

}  // namespace landsim::scenes::detail
