#include "trees/harmonic/layout.h"

#include <string>

namespace landsim::trees::harmonic {
namespace {

constexpr BlockShape kBlocks[] = {
    {"general", 0, 8, 1}, {"hierarchy", 8, 9, 4},  {"arc", 44, 8, 3},
    {"wander", 68, 2, 4}, {"harmonics", 76, 3, 4}, {"semantic", 88, 12, 1},
};

// One row of each block: name, valid range, discovery range, whole number.
constexpr ParameterSpec kGeneral[8] = {
    {"max_age", 5, 400, 40, 120, true},
    {"step_length", 0.005, 2, 0.05, 0.15},
    {"levels", 3, 5, 3, 5, true},
    {"girth_rate", 0, 0.01, 0.0003, 0.001},
    {"tip_radius", 0.0005, 0.05, 0.002, 0.006},
    {"wander_noise", 0, 1, 0, 0.5},
    {"variation", 0, 0.3, 0.02, 0.1},
    {"tropism", -10, 10, -1, 2},
};
constexpr ParameterSpec kHierarchy[9] = {
    {"node_spacing", 1, 50, 2, 8, true},  {"node_probability", 0, 1, 0.5, 1},
    {"branch_probability", 0, 1, 0.3, 1}, {"branch_angle", 0, 120, 20, 80},
    {"divergence", 0, 360, 90, 180},      {"terminal_age", 1, 400, 10, 80, true},
    {"radius_ratio", 0.05, 1, 0.4, 0.9},  {"twist", -45, 45, -5, 5},
    {"step_scale", 0.1, 2, 0.6, 1.0},
};
constexpr ParameterSpec kArc[8] = {
    {"span1", 0, 400, 2, 20, true}, {"bend1", -90, 90, -40, 40},    {"span2", 0, 400, 2, 20, true},
    {"bend2", -90, 90, -40, 40},    {"span3", 0, 400, 2, 20, true}, {"bend3", -90, 90, -40, 40},
    {"span4", 0, 400, 2, 20, true}, {"bend4", -90, 90, -40, 40},
};
constexpr ParameterSpec kWander[2] = {
    {"wander_angle", 0, 90, 0, 20},
    {"wander_interval", 1, 100, 2, 10, true},
};
constexpr ParameterSpec kHarmonic[3] = {
    {"frequency", 0, 3.2, 0, 1.0},
    {"amplitude", 0, 30, 0, 6},
    {"phase", 0, 360, 0, 360},
};
constexpr ParameterSpec kSemantic[12] = {
    {"leaf_spacing", 1, 50, 1, 4, true},   {"leaf_probability", 0, 1, 0.5, 1},
    {"leaf_size", 0.005, 1, 0.04, 0.15},   {"leaf_tilt_limit", 0, 90, 10, 60},
    {"leaf_level", 0, 5, 1, 3, true},      {"leaf_aspect", 0.05, 2, 0.2, 0.8},
    {"part_spacing", 1, 100, 4, 20, true}, {"part_probability", 0, 1, 0, 0.5},
    {"part_size", 0.005, 0.5, 0.02, 0.08}, {"part_kind", 0, 1, 0, 1, true},
    {"part_level", 0, 5, 2, 4, true},      {"leaf_droop", -90, 90, -30, 30},
};

template <std::size_t N>
void place(std::array<ParameterSpec, kParameterCount>& out, const BlockShape& b,
           const ParameterSpec (&row)[N]) {
  for (std::size_t r = 0; r < b.rows; ++r)
    for (std::size_t k = 0; k < N; ++k) out[b.offset + r * N + k] = row[k];
}

}  // namespace

const BlockShape& block_shape(Block block) { return kBlocks[static_cast<int>(block)]; }

const std::array<ParameterSpec, kParameterCount>& parameter_specs() {
  static const auto specs = [] {
    std::array<ParameterSpec, kParameterCount> s{};
    place(s, kBlocks[0], kGeneral);
    place(s, kBlocks[1], kHierarchy);
    place(s, kBlocks[2], kArc);
    place(s, kBlocks[3], kWander);
    place(s, kBlocks[4], kHarmonic);
    place(s, kBlocks[5], kSemantic);
    return s;
  }();
  return specs;
}

std::string parameter_label(std::size_t i) {
  for (const BlockShape& b : kBlocks) {
    if (i < b.offset || i >= b.offset + b.per_row * b.rows) continue;
    std::string label = b.key;
    if (b.rows > 1)
      label.append("[").append(std::to_string((i - b.offset) / b.per_row)).append("]");
    label += ".";
    label += parameter_specs()[i].name;
    return label;
  }
  return "?";
}

}  // namespace landsim::trees::harmonic
