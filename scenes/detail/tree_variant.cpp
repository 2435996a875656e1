#include "scenes/detail/tree_variant.h"

#include <algorithm>

#include "core/counter_rng.h"
#include "trees/species.h"

namespace landsim::scenes::detail {
namespace {

std::uint64_t variant_seed(std::uint64_t seed, int bit, std::uint32_t variant) {
  return hash_combine(hash_combine(seed, static_cast<std::uint64_t>(bit)), variant);
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
  return p;
}

}  // namespace landsim::scenes::detail
