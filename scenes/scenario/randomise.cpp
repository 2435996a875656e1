#include "scenes/scenario/randomise.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "core/counter_rng.h"
#include "core/fnv_hash.h"
#include "core/input_error.h"
#include "scenes/scenario/render_choices.h"

namespace landsim::scenes {
namespace {

std::string number_text(double v, bool integer) {
  return integer ? fmt::format("{}", static_cast<std::int64_t>(v)) : fmt::format("{}", v);
}

// One key's draw as TOML text.
std::string draw(const RandomKey& k, const CounterRng& rng) {
  if (k.kind == RandomKey::Kind::choose) {
    const auto n = k.choices.size();
    return k.choices[std::min(n - 1,
                              static_cast<std::size_t>(rng.uniform(0) * static_cast<double>(n)))];
  }
  std::vector<std::string> parts;
  for (std::size_t c = 0; c < k.hi.size(); ++c) {
    const double u = rng.uniform(static_cast<std::uint32_t>(c));
    double v = 0.0;
    if (k.kind == RandomKey::Kind::jitter) {
      v = k.base[c] + (2.0 * u - 1.0) * k.hi[c];
    } else if (k.integer) {  // inclusive: each of lo..hi alike
      v = std::min(k.hi[c], k.lo[c] + std::floor(u * (k.hi[c] - k.lo[c] + 1.0)));
    } else {
      v = k.lo[c] + u * (k.hi[c] - k.lo[c]);
    }
    parts.push_back(number_text(v, k.integer));
  }
  return k.vector ? "[" + fmt::format("{}", fmt::join(parts, ", ")) + "]" : parts[0];
}

}  // namespace

std::size_t randomised_images(const Scenario& s) {
  return s.randomise ? static_cast<std::size_t>(s.randomise->images) : 1;
}

std::vector<std::string> randomised_sets(const Scenario& s, std::size_t image) {
  std::vector<std::string> out;
  if (!s.randomise) return out;
  const std::uint64_t seed = hash_combine(s.render.seed, s.randomise->seed);
  for (const RandomKey& k : s.randomise->keys)
    out.push_back(k.key + "=" + draw(k, CounterRng(seed, image, fnv1a(k.key))));
  return out;
}

Scenario randomised_scenario(const Scenario& s, std::size_t image) {
  if (!s.randomise) return s;
  const RandomiseSettings& r = *s.randomise;
  const std::vector<std::string> draws = randomised_sets(s, image);
  std::vector<std::string> sets = r.sets;
  sets.insert(sets.end(), draws.begin(), draws.end());
  Scenario out;
  try {
    out = parse_scenario(r.text, r.source, r.base_dir, sets);
  } catch (const InputError& e) {
    throw InputError(fmt::format("{}: [randomise] image {} drew a value the scenario refuses: {}",
                                 r.location, image, e.what()));
  }
  apply_render_choices(out, s.choices);  // the command line's spp, size, view
  // The set's images are counted from the file's views and frames: a draw may move them,
  // not add or remove them.
  if (out.views.size() != s.views.size() || out.render.frames.size() != s.render.frames.size())
    throw InputError(
        fmt::format("{}: [randomise] image {} has {} views and {} frames, the set "
                    "{} and {}: draws may change views and frames, not their number",
                    r.location, image, out.views.size(), out.render.frames.size(), s.views.size(),
                    s.render.frames.size()));
  out.variation = image + 1;
  out.variation_sets = draws;
  return out;
}

}  // namespace landsim::scenes
