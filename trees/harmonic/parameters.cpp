#include "trees/harmonic/parameters.h"

#include "trees/harmonic/particle_growth.h"

#include <toml++/toml.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <optional>

#include "core/input_error.h"
#include "params/table_reader.h"
#include "trees/random.h"

namespace landsim::trees::harmonic {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;
constexpr Block kBlocks[] = {Block::general, Block::hierarchy, Block::arc,
                             Block::wander,  Block::harmonic,  Block::semantic};

double clamp_to_spec(double v, std::size_t i) {
  const ParameterSpec& s = parameter_specs()[i];
  v = std::clamp(v, s.min, s.max);
  return s.whole ? std::round(v) : v;
}

// One row of a block: exactly `per_row` numbers, each in its range.
void read_row(params::TableReader& r, const toml::node& n, const BlockShape& b, std::size_t row,
              Parameters& p) {
  const toml::array* a = n.as_array();
  if (a == nullptr || a->size() != b.per_row)
    r.fail_at(n, b.key,
              "expected " + std::string(b.rows > 1 ? "row " + std::to_string(row) + ": " : "") +
                  std::to_string(b.per_row) + " numbers (docs/HARMONIC.md)");
  for (std::size_t k = 0; k < b.per_row; ++k) {
    const std::size_t i = b.offset + row * b.per_row + k;
    const ParameterSpec& s = parameter_specs()[i];
    const auto v = a->get(k)->value<double>();
    const params::Range range{s.min, s.max};
    if (!v || !range.contains(*v) || (s.whole && *v != std::round(*v)))
      r.fail_at(*a->get(k), b.key,
                parameter_label(i) + ": expected " + (s.whole ? "a whole number " : "a number ") +
                    range.describe());
    p.values[i] = *v;
  }
}

void read_block(params::TableReader& r, const BlockShape& b, Parameters& p) {
  const std::string shape =
      b.rows == 1 ? std::to_string(b.per_row) + " numbers"
                  : std::to_string(b.rows) + " rows of " + std::to_string(b.per_row) + " numbers";
  const toml::node* n = r.value(b.key, shape, "the middle of each range");
  if (n == nullptr) return;
  if (b.rows == 1) return read_row(r, *n, b, 0, p);
  const toml::array* a = n->as_array();
  if (a == nullptr || a->size() != b.rows) r.fail(b.key, "expected " + shape);
  for (std::size_t row = 0; row < b.rows; ++row) read_row(r, *a->get(row), b, row, p);
}

// harmonic_terms = [[level, frequency, amplitude, phase], ...]: at most three per level, so
// that with the layout's own a level sums the paper's four terms.
void read_terms(params::TableReader& r, Parameters& p) {
  const std::string expected =
      "[[level, frequency, amplitude, phase], ...]: level 0-3, frequency 0-3.2 radians per "
      "step, amplitude 0-30 degrees, phase 0-360 degrees";
  const toml::node* n = r.value("harmonic_terms", expected, "none");
  if (n == nullptr) return;
  const toml::array* a = n->as_array();
  if (a == nullptr) r.fail("harmonic_terms", "expected " + expected);
  std::array<int, 4> per_level{};
  for (const toml::node& row : *a) {
    const toml::array* q = row.as_array();
    std::array<std::optional<double>, 4> v;
    for (std::size_t k = 0; k < 4 && q != nullptr && q->size() == 4; ++k)
      v[k] = q->get(k)->value<double>();
    // Frequency, amplitude and phase within the harmonics row's own ranges.
    const std::size_t first = block_shape(Block::harmonic).offset;
    bool in_range = v[0] && *v[0] == std::round(*v[0]) && *v[0] >= 0 && *v[0] <= 3;
    for (std::size_t k = 1; k < 4 && in_range; ++k) {
      const ParameterSpec& spec = parameter_specs()[first + k - 1];
      in_range = v[k] && *v[k] >= spec.min && *v[k] <= spec.max;
    }
    if (!in_range) r.fail_at(row, "harmonic_terms", "expected " + expected);
    const int level = static_cast<int>(*v[0]);
    if (++per_level[static_cast<std::size_t>(level)] > 3)
      r.fail_at(row, "harmonic_terms",
                "expected at most 3 further terms for level " + std::to_string(level) +
                    " (with the harmonics row, the paper's 4)");
    p.terms.push_back({level, *v[1], *v[2] * kDegree, *v[3] * kDegree});
  }
}

void read_elongation(params::TableReader r, Elongation& e) {
  e.initial = r.number("initial", {0.05, 1}, e.initial);
  e.steps = static_cast<int>(r.integer("steps", 0, 400, e.steps));
  r.finish();
}

PartSettings read_part(params::TableReader& r) {
  PartSettings s;
  const std::string kind = r.choice("kind", {"flower", "thorn", "bud"});
  s.kind = kind == "flower" ? PartKind::flower : kind == "thorn" ? PartKind::thorn : PartKind::bud;
  s.at_nodes = r.boolean("at_nodes", s.at_nodes);
  s.spacing = static_cast<int>(r.integer("spacing", 1, 100, s.spacing));
  s.probability = r.number("probability", {0, 1}, s.probability);
  s.size = r.number("size", {0.001, 0.5}, s.size);
  s.level = static_cast<int>(r.integer("level", 0, 5, s.level));
  s.angle = r.angle("angle", {0, 180}, s.angle);
  s.petals = static_cast<int>(r.integer("petals", 3, 12, s.petals));
  r.finish();
  return s;
}

}  // namespace

double Parameters::at(Block b, std::size_t row, std::size_t k) const {
  const BlockShape& s = block_shape(b);
  return values[s.offset + std::min(row, s.rows - 1) * s.per_row + k];
}

LevelParameters Parameters::level(int i) const {
  const auto row = static_cast<std::size_t>(std::max(i, 0));
  const auto v = [&](std::size_t k) { return at(Block::hierarchy, row, k); };
  return {static_cast<int>(v(0)),
          v(1),
          v(2),
          v(3) * kDegree,
          v(4) * kDegree,
          static_cast<int>(v(5)),
          v(6),
          v(7) * kDegree,
          v(8)};
}

std::array<ArcSection, 4> Parameters::arc(int level) const {
  std::array<ArcSection, 4> sections{};
  for (std::size_t k = 0; k < 4; ++k)
    sections[k] = {static_cast<int>(at(Block::arc, static_cast<std::size_t>(level), 2 * k)),
                   at(Block::arc, static_cast<std::size_t>(level), 2 * k + 1) * kDegree};
  return sections;
}

double Parameters::wander_angle(int level) const {
  return at(Block::wander, static_cast<std::size_t>(level), 0) * kDegree;
}
int Parameters::wander_interval(int level) const {
  return static_cast<int>(at(Block::wander, static_cast<std::size_t>(level), 1));
}
double Parameters::harmonic_frequency(int level) const {
  return at(Block::harmonic, static_cast<std::size_t>(level), 0);
}
double Parameters::harmonic_amplitude(int level) const {
  return at(Block::harmonic, static_cast<std::size_t>(level), 1) * kDegree;
}
double Parameters::harmonic_phase(int level) const {
  return at(Block::harmonic, static_cast<std::size_t>(level), 2) * kDegree;
}

double Parameters::harmonic_turn(int level, int age) const {
  double turn =
      harmonic_amplitude(level) * std::sin(age * harmonic_frequency(level) + harmonic_phase(level));
  for (const HarmonicTerm& t : terms)
    if (t.level == std::min(level, 3)) turn += t.amplitude * std::sin(age * t.frequency + t.phase);
  return turn;
}

Parameters default_parameters() {
  Parameters p;
  const auto& specs = parameter_specs();
  for (std::size_t i = 0; i < kParameterCount; ++i)
    p.values[i] = clamp_to_spec(0.5 * (specs[i].discover_min + specs[i].discover_max), i);
  return p;
}

Parameters read_parameters(params::TableReader& root, const std::string& /*source*/) {
  Parameters p = default_parameters();
  for (Block b : kBlocks) read_block(root, block_shape(b), p);
  read_terms(root, p);
  read_elongation(root.table("elongation"), p.elongation);
  for (params::TableReader& t : root.tables("part")) p.parts.push_back(read_part(t));
  // An explosive species is refused here, at its file, before anything grows.
  if (const auto why = too_many_particles(p, -1, kMaxParticles)) root.fail("hierarchy", *why);
  return p;
}

Parameters vary(const Parameters& p, std::uint64_t seed) {
  Parameters out = p;
  const double v = p.variation();
  if (v <= 0.0) return out;
  Random rng(seed, 0x4a12u);
  for (std::size_t i = 0; i < kParameterCount; ++i)
    out.values[i] = clamp_to_spec(p.values[i] * (1.0 + v * rng.uniform(-1.0, 1.0)), i);
  out.values[2] = p.values[2];  // the number of levels is the species'
  return out;
}

Parameters sample_discovery(std::uint64_t seed) {
  Parameters p;
  Random rng(seed, 0xd15cu);
  const auto& specs = parameter_specs();
  for (std::size_t i = 0; i < kParameterCount; ++i)
    p.values[i] = clamp_to_spec(rng.uniform(specs[i].discover_min, specs[i].discover_max), i);
  return p;
}

namespace {

std::string number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", v);
  return text;
}

// The keys beyond the 100 floats, when set: harmonic_terms, then the [elongation] and
// [[part]] tables (after every top-level key, as TOML needs).
std::string format_extensions(const Parameters& p) {
  std::string out;
  if (!p.terms.empty()) {
    out += "harmonic_terms = [";
    for (std::size_t i = 0; i < p.terms.size(); ++i) {
      const HarmonicTerm& t = p.terms[i];
      out += (i == 0 ? "[" : ", [") + std::to_string(t.level) + ", " + number(t.frequency) + ", " +
             number(t.amplitude / kDegree) + ", " + number(t.phase / kDegree) + "]";
    }
    out += "]\n";
  }
  if (p.elongation.steps > 0)
    out += "[elongation]\ninitial = " + number(p.elongation.initial) +
           "\nsteps = " + std::to_string(p.elongation.steps) + "\n";
  for (const PartSettings& s : p.parts) {
    const char* kind = s.kind == PartKind::flower  ? "flower"
                       : s.kind == PartKind::thorn ? "thorn"
                                                   : "bud";
    out += std::string("[[part]]\nkind = \"") + kind +
           "\"\nat_nodes = " + (s.at_nodes ? "true" : "false") +
           "\nspacing = " + std::to_string(s.spacing) + "\nprobability = " + number(s.probability) +
           "\nsize = " + number(s.size) + "\nlevel = " + std::to_string(s.level) +
           "\nangle = " + number(s.angle / kDegree) + "\npetals = " + std::to_string(s.petals) +
           "\n";
  }
  return out;
}

}  // namespace

std::string format_parameters(const Parameters& p) {
  std::string out;
  for (Block b : kBlocks) {
    const BlockShape& s = block_shape(b);
    out += s.key;
    out += " = [";
    for (std::size_t row = 0; row < s.rows; ++row) {
      if (s.rows > 1) out += row == 0 ? "[" : ", [";
      for (std::size_t k = 0; k < s.per_row; ++k) {
        char number[32];
        std::snprintf(number, sizeof number, "%.17g", p.values[s.offset + row * s.per_row + k]);
        out += (k == 0 ? "" : ", ") + std::string(number);
      }
      if (s.rows > 1) out += "]";
    }
    out += "]\n";
  }
  return out + format_extensions(p);
}

}  // namespace landsim::trees::harmonic
