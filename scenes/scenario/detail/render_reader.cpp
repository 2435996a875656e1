#include "scenes/scenario/detail/render_reader.h"

#include <fmt/format.h>

#include <cstdint>

#include "params/table_reader.h"
#include "trees/species.h"

namespace landsim::scenes::detail {

namespace {

using params::Range;
using params::TableReader;

// "auto", or an exposure value at ISO 100: -6 (a moonlit night) to 24 (beyond any sunlit
// scene), the range a photographer's exposure table spans.
std::optional<double> read_exposure(TableReader& r) {
  const toml::node* n = r.value("exposure", "\"auto\" or an EV100 from -6 to 24", "\"auto\"");
  if (n == nullptr) return std::nullopt;
  if (const auto* s = n->as_string(); s != nullptr && s->get() == "auto") return std::nullopt;
  if (const auto* s = n->as_string())
    r.fail_at(*n, "exposure",
              "expected \"auto\" or an EV100 from -6 to 24, got \"" + s->get() + "\"");
  if (!n->is_number()) r.fail_at(*n, "exposure", "expected \"auto\" or an EV100 from -6 to 24");
  const double ev = n->value<double>().value_or(0.0);
  if (!(ev >= -6.0 && ev <= 24.0))
    r.fail_at(*n, "exposure",
              fmt::format("expected \"auto\" or an EV100 from -6 to 24, got {}", ev));
  return ev;
}

// [render] formats: "exr" (always written: the set's own record) and optionally "geotiff",
// "envi".
void read_formats(TableReader& r, RenderSection& s) {
  const toml::node* n =
      r.value("formats", "an array of \"exr\", \"geotiff\", \"envi\"", "[\"exr\"]");
  if (n == nullptr) return;
  const toml::array* a = n->as_array();
  if (a == nullptr) r.fail_at(*n, "formats", "expected an array such as [\"exr\", \"geotiff\"]");
  bool exr = false;
  for (const toml::node& f : *a) {
    const std::optional<std::string> name = f.value<std::string>();
    if (!name || (*name != "exr" && *name != "geotiff" && *name != "envi"))
      r.fail_at(f, "formats", "expected \"exr\", \"geotiff\" or \"envi\"");
    exr |= *name == "exr";
    s.geotiff |= *name == "geotiff";
    s.envi |= *name == "envi";
  }
  if (!exr)
    r.fail_at(*n, "formats",
              "must include \"exr\" (the image set's own record, read by --resume "
              "and compare)");
}

}  // namespace

RenderSection read_render(const toml::table& t, const std::string& file) {
  TableReader r(t, "render", file);
  RenderSection s;
  s.spp = static_cast<int>(r.integer("spp", 1, kMaxSpp, s.spp));
  s.noise_threshold = r.number("noise_threshold", Range{0.0, 1.0}, s.noise_threshold);
  if (r.has("min_spp")) {
    if (!(s.noise_threshold > 0.0))
      r.fail("min_spp", "is for adaptive sampling: give noise_threshold (above 0) too");
    s.min_spp = static_cast<int>(r.integer("min_spp", 1, s.spp));
  }
  s.seed = static_cast<std::uint64_t>(r.integer("seed", 0, INT64_MAX, s.seed));
  const char* sampler = s.sampler == SampleSequence::sobol ? "sobol" : "independent";
  s.sampler = r.choice("sampler", {"independent", "sobol"}, sampler) == "sobol"
                  ? SampleSequence::sobol
                  : SampleSequence::independent;
  if (r.has("sampling_seed"))
    s.sampling_seed = static_cast<std::uint64_t>(r.integer("sampling_seed", 0, INT64_MAX));
  s.threads = static_cast<int>(r.integer("threads", 0, 1024, s.threads));
  s.max_bounces = static_cast<int>(r.integer("max_bounces", -1, 1000000, s.max_bounces));
  s.exposure_ev100 = read_exposure(r);
  s.checkpoint_seconds = r.number("checkpoint_seconds", Range{0.0, 1e6}, s.checkpoint_seconds);
  s.season = *trees::season_from_name(
      r.choice("season", {"spring", "summer", "autumn", "winter"}, "summer"));
  s.degradation = r.boolean("degradation", s.degradation);
  s.quality = r.number("quality", Range{0.0, 1.0, true, false}, s.quality);
  s.max_memory = r.byte_size("max_memory");
  s.reflectance = r.boolean("reflectance", s.reflectance);
  s.atmosphere_layers = r.boolean("atmosphere_layers", s.atmosphere_layers);
  s.illumination_layers = r.boolean("illumination_layers", s.illumination_layers);
  s.guiding = r.boolean("guiding", s.guiding);
  s.guiding_training = r.number("guiding_training", Range{0.01, 1.0}, s.guiding_training);
  read_formats(r, s);
  if (r.has("frames")) {
    const toml::node* n = t.get("frames");
    const toml::array* a = n->as_array();
    if (a == nullptr || a->empty() || a->size() > static_cast<std::size_t>(kMaxFrames)) {
      r.fail("frames",
             "expected an array of 1 to " + std::to_string(kMaxFrames) + " times in seconds");
    }
    s.frames = r.numbers("frames", a->size(), Range{0.0, 1e9});
  } else {
    r.numbers("frames", 1, Range{0.0, 1e9}, std::vector<double>{0.0});
  }
  r.finish();
  return s;
}

}  // namespace landsim::scenes::detail
