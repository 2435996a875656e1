#include "trees/harmonic/parameters.h"

#include <toml++/toml.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

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
  return out;
}

}  // namespace landsim::trees::harmonic
