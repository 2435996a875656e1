#pragma once
// The directional half of practical path guiding (Müller, Gross and Novák 2017, section 3.2):
// a quadtree over the square that the cylindrical mapping (cos theta, phi) lays the sphere of
// directions on, area for area, so that a density over the square is one over solid angle up
// to the constant 4 pi. Each node holds the flux its four quadrants received in the training
// records; a quadrant holding more than a share rho of the whole is subdivided (section 3.3),
// so that the tree is fine where light arrives from and coarse elsewhere. Sampling descends
// in proportion to the flux; the density is the product of the choices' shares.
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "core/vec3.h"

namespace landsim::renderer {

// One training record as the directional tree sees it: a direction in the square and the
// flux it carried (the incident radiance over the density it was sampled with).
struct DirectionalRecord {
  float u = 0.0f, v = 0.0f;  // (cos theta + 1) / 2, phi / 2 pi
  float flux = 0.0f;
};

// The square's point of a direction, and back (the cylindrical mapping: equal areas).
std::array<float, 2> direction_to_square(const Vec3f& d);
Vec3f square_to_direction(float u, float v);

class DirectionalTree {
 public:
  // A subdivided quadrant holds more than this share of the whole flux (Müller et al. 2017,
  // section 3.3: rho = 0.01), down to kMaxDepth levels (a quadrant of 2^-20 of the square).
  static constexpr float kSubdivideShare = 0.01f;
  static constexpr int kMaxDepth = 20;
  // A quadrant is subdivided only when it holds this many records: deeper, a few records'
  // flux would pick out their own directions and leave empty quadrants between them
  // (measured on ndvi.toml's near infrared: with 2, its noise guided was 0.59; with 32, 0.37).
  static constexpr std::size_t kLeastSplitRecords = 32;
  // Each quadrant is drawn in proportion to its flux mixed with this share of its node's
  // flux spread evenly: no quadrant that a sparse sample left dark is never drawn.
  static constexpr double kFloor = 0.05;

  DirectionalTree() = default;
  // Built from the records of one spatial region; `records` is reordered. Empty (no
  // density) when the records carry no flux.
  explicit DirectionalTree(std::span<DirectionalRecord> records);

  bool empty() const { return nodes_.empty(); }
  // A direction drawn in proportion to the learned flux, and its solid-angle density.
  Vec3f sample(float u1, float u2, float& pdf) const;
  float pdf(const Vec3f& d) const;
  // The density over the square at (u, v): integrates to 1 over [0, 1)^2.
  float square_pdf(float u, float v) const;
  std::size_t node_count() const { return nodes_.size(); }

 private:
  // A node's four quadrants: index x + 2 y (x, y: the upper half of each axis); a child of
  // 0 is a leaf quadrant (no node below it).
  struct Node {
    std::array<float, 4> flux{};
    std::array<std::uint32_t, 4> child{};
  };
  std::uint32_t build(std::span<DirectionalRecord> records, float x0, float y0, float size,
                      double total, int depth);
  std::vector<Node> nodes_;
};

}  // namespace landsim::renderer
