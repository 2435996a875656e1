#include "scenes/builder/detail/tree_variant.h"

#include <algorithm>
#include <memory>

#include "core/counter_rng.h"
#include "renderer/spectra/spectral_colour.h"
#include "renderer/spectra/vegetation_optics.h"
#include "trees/species.h"

namespace landsim::scenes::detail {
namespace {

std::uint64_t variant_seed(std::uint64_t seed, int bit, std::uint32_t variant) {
  return hash_combine(hash_combine(seed, static_cast<std::uint64_t>(bit)), variant);
}

// A variant's leaf contents (docs/SPECTRAL.md "Seasons"): each pigment varied by up to
// +-`variation` and the structure by half that (brighter or darker leaves); young spring
// leaves with half the chlorophyll; autumn leaves, each variant its own way, yellow
// (carotenoids unmasked), orange or red (anthocyanins), with brown pigments.
trees::LeafContents seasonal_leaf(trees::LeafContents c, trees::Season season, float variation,
                                  const CounterRng& r) {
  if (season == trees::Season::spring) {
    c.chlorophyll *= 0.5;
    c.carotenoids *= 0.6;
  } else if (season == trees::Season::autumn) {
    struct Turn {
      double chlorophyll, carotenoids, anthocyanins, brown;
    };
    static constexpr Turn kAutumn[3] = {
        {4.0, 10.0, 0.0, 0.2}, {3.0, 8.0, 5.0, 0.4}, {3.0, 4.0, 15.0, 0.3}};
    const Turn& t = kAutumn[std::min(2, static_cast<int>(r.uniform(4) * 3.0f))];
    c.chlorophyll = t.chlorophyll;
    c.carotenoids = t.carotenoids;
    c.anthocyanins = t.anthocyanins;
    c.brown = t.brown;
  }
  const auto vary = [&](std::uint32_t dim, double amount) {
    return 1.0 + amount * (2.0 * r.uniform(dim) - 1.0);
  };
  c.chlorophyll *= vary(0, variation);
  c.carotenoids *= vary(1, variation);
  c.anthocyanins *= vary(2, variation);
  c.structure = std::clamp(c.structure * vary(3, 0.5 * variation), 1.0, 3.5);
  return c;
}

}  // namespace

renderer::TreePrototype make_tree_variant(const Scenario& s, std::uint32_t species_index,
                                          std::uint32_t variant, double time,
                                          std::uint32_t phase_group) {
  const SpeciesSettings& sp = s.species[species_index];
  renderer::TreePrototype p;
  const std::uint64_t vs = variant_seed(s.render.seed, sp.bit, variant);
  const trees::Season season = s.render.season;
  trees::TreeOptions options;
  options.seed = vs;
  options.time = time;
  options.quality = s.render.quality;
  // Ages: evenly from the youngest to the oldest across the variants (every core).
  if (sp.age_min >= 0.0)
    options.age = sp.variants > 1
                      ? sp.age_min + (sp.age_max - sp.age_min) * variant / (sp.variants - 1)
                      : sp.age_min;
  options.wind_speed = s.wind.speed;
  options.wind_gust = s.wind.gust;
  // Group 0 sways with the variant's own phases; the others with phases of their own.
  if (phase_group > 0) options.sway_seed = hash_combine(hash_combine(vs, 0x5741u), phase_group);
  p.geometry = trees::generate(sp.species, options).geometry;
  p.degradation = trees::degradation_factors(s.render.quality, season, sp.evergreen);
  p.species = static_cast<std::uint16_t>(species_index);
  p.dress(sp.species.colours);
  // Per-variant colour variation: one brightness factor and a slight hue shift.
  const CounterRng r(vs, 17, 0);
  const auto v = static_cast<float>(sp.colour_variation);
  const Vec3f factor{1.0f + v * (2.0f * r.uniform(0) - 1.0f),
                     1.0f + v * (2.0f * r.uniform(1) - 1.0f),
                     1.0f + v * (2.0f * r.uniform(2) - 1.0f)};
  const float brightness = 1.0f + v * (2.0f * r.uniform(3) - 1.0f);
  p.leaf_reflectance = sp.species.colours.leaf * factor * brightness;
  if (!sp.evergreen) {
    if (season == trees::Season::spring) {
      p.leaf_reflectance = p.leaf_reflectance * Vec3f{1.25f, 1.3f, 0.7f};  // young, yellower green
    } else if (season == trees::Season::autumn) {
      // Each variant turns its own way between yellow, orange and red.
      static constexpr Vec3f kAutumn[3] = {
          {0.45f, 0.35f, 0.05f}, {0.45f, 0.18f, 0.03f}, {0.35f, 0.07f, 0.03f}};
      p.leaf_reflectance = kAutumn[std::min(2, static_cast<int>(r.uniform(4) * 3.0f))] * brightness;
    } else if (season == trees::Season::winter) {
      p.geometry.group(trees::Group::leaves) = trees::GroupGeometry{};  // leafless
    }
  }
  p.leaf_transmittance = p.leaf_reflectance * renderer::kLeafTransmittanceRatio;
  const trees::GroupGeometry& leaves = p.geometry.group(trees::Group::leaves);
  if (leaves.triangles.triangle_count() == 0 && leaves.points.point_count() == 0) return p;
  if (const auto& contents = sp.species.colours.leaf_optics) {
    // The leaves' spectra from their contents, varied per variant and by season; their
    // colour (the film's albedo, the POV-Ray export, the comparable tracer) follows.
    const trees::LeafContents leaf =
        seasonal_leaf(*contents, sp.evergreen ? trees::Season::summer : season, v, r);
    auto optics = std::make_shared<renderer::SpectralOptics>(renderer::leaf_spectral_optics(leaf));
    p.leaf_reflectance = renderer::reflectance_rgb(optics->reflectance);
    p.leaf_transmittance = renderer::reflectance_rgb(optics->transmittance);
    p.leaf_optics = std::move(optics);
  } else {
    p.leaf_optics = std::make_shared<renderer::SpectralOptics>(
        renderer::coloured_leaf_optics(p.leaf_reflectance, p.leaf_transmittance));
  }
  return p;
}

}  // namespace landsim::scenes::detail
