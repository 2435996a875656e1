#include "renderer/guiding/directional_tree.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace landsim::renderer {
namespace {

constexpr float kPi = std::numbers::pi_v<float>;
constexpr float kBelowOne = 0.99999994f;

}  // namespace

std::array<float, 2> direction_to_square(const Vec3f& d) {
  const float u = std::clamp((d.z + 1.0f) * 0.5f, 0.0f, kBelowOne);
  float phi = std::atan2(d.y, d.x) / (2.0f * kPi);
  if (phi < 0.0f) phi += 1.0f;
  return {u, std::clamp(phi, 0.0f, kBelowOne)};
}

Vec3f square_to_direction(float u, float v) {
  const float cos_theta = 2.0f * u - 1.0f;
  const float sin_theta = std::sqrt(std::max(0.0f, 1.0f - cos_theta * cos_theta));
  const float phi = 2.0f * kPi * v;
  return {sin_theta * std::cos(phi), sin_theta * std::sin(phi), cos_theta};
}

DirectionalTree::DirectionalTree(std::span<DirectionalRecord> records) {
  double total = 0.0;
  for (const DirectionalRecord& r : records) total += r.flux;
  if (total > 0.0) build(records, 0.0f, 0.0f, 1.0f, total, 0);
}

std::uint32_t DirectionalTree::build(std::span<DirectionalRecord> records, float x0, float y0,
                                     float size, double total, int depth) {
  const auto index = static_cast<std::uint32_t>(nodes_.size());
  nodes_.emplace_back();
  const float half = size * 0.5f;
  // Quadrant x + 2 y: split the records by u, then each half by v.
  const auto right = std::partition(records.begin(), records.end(),
                                    [&](const DirectionalRecord& r) { return r.u < x0 + half; });
  const auto upper = [&](auto b, auto e) {
    return std::partition(b, e, [&](const DirectionalRecord& r) { return r.v < y0 + half; });
  };
  const auto left_top = upper(records.begin(), right);
  const auto right_top = upper(right, records.end());
  const std::array<std::span<DirectionalRecord>, 4> quadrant{
      std::span(records.begin(), left_top), std::span(right, right_top), std::span(left_top, right),
      std::span(right_top, records.end())};
  std::array<double, 4> flux{};
  for (int q = 0; q < 4; ++q)
    for (const DirectionalRecord& r : quadrant[static_cast<std::size_t>(q)])
      flux[static_cast<std::size_t>(q)] += r.flux;
  const double node_flux = flux[0] + flux[1] + flux[2] + flux[3];
  for (int q = 0; q < 4; ++q) {
    const auto& part = quadrant[static_cast<std::size_t>(q)];
    const double own = flux[static_cast<std::size_t>(q)];
    nodes_[index].flux[static_cast<std::size_t>(q)] =
        static_cast<float>((1.0 - kFloor) * own + kFloor * 0.25 * node_flux);
    // Subdivided while it holds more than its share and records enough to resolve it.
    if (own > kSubdivideShare * total && depth + 1 < kMaxDepth &&
        part.size() >= kLeastSplitRecords) {
      const std::uint32_t child =
          build(part, x0 + static_cast<float>(q & 1) * half, y0 + static_cast<float>(q >> 1) * half,
                half, total, depth + 1);
      nodes_[index].child[static_cast<std::size_t>(q)] = child;
    }
  }
  return index;
}

Vec3f DirectionalTree::sample(float u1, float u2, float& pdf) const {
  // Each level's choice rescales the numbers that made it (in double: twenty levels keep
  // enough bits to place the point within its last quadrant).
  double du = u1, dv = u2, x0 = 0.0, y0 = 0.0, size = 1.0;
  std::uint32_t node = 0;
  float density = 1.0f;
  while (true) {
    const std::array<float, 4>& f = nodes_[node].flux;
    const double total = static_cast<double>(f[0]) + f[1] + f[2] + f[3];
    // The column by its flux, then the row within it.
    const double left = (static_cast<double>(f[0]) + f[2]) / total;
    const int x = du < left ? 0 : 1;
    du = x == 0 ? du / left : (du - left) / (1.0 - left);
    const double lower =
        static_cast<double>(f[static_cast<std::size_t>(x)]) /
        (static_cast<double>(f[static_cast<std::size_t>(x)]) + f[static_cast<std::size_t>(x + 2)]);
    const int y = dv < lower ? 0 : 1;
    dv = y == 0 ? dv / lower : (dv - lower) / (1.0 - lower);
    const auto q = static_cast<std::size_t>(x + 2 * y);
    density *= static_cast<float>(4.0 * f[q] / total);
    size *= 0.5;
    x0 += x * size;
    y0 += y * size;
    if (nodes_[node].child[q] == 0) break;
    node = nodes_[node].child[q];
  }
  // Rounded to float, a point may not reach its quadrant's far edge (the next quadrant's).
  const auto inside = [&](double origin, double t) {
    const auto edge = static_cast<float>(origin + size);
    const auto p = static_cast<float>(origin + std::clamp(t, 0.0, 1.0) * size);
    return std::min(p < edge ? p : std::nextafter(edge, 0.0f), kBelowOne);
  };
  pdf = density / (4.0f * kPi);
  return square_to_direction(inside(x0, du), inside(y0, dv));
}

float DirectionalTree::square_pdf(float u, float v) const {
  if (nodes_.empty()) return 0.0f;
  float x0 = 0.0f, y0 = 0.0f, size = 1.0f, density = 1.0f;
  std::uint32_t node = 0;
  while (true) {
    const std::array<float, 4>& f = nodes_[node].flux;
    const float total = f[0] + f[1] + f[2] + f[3];
    size *= 0.5f;
    const int x = u < x0 + size ? 0 : 1, y = v < y0 + size ? 0 : 1;
    const auto q = static_cast<std::size_t>(x + 2 * y);
    if (!(f[q] > 0.0f)) return 0.0f;
    density *= 4.0f * f[q] / total;
    x0 += static_cast<float>(x) * size;
    y0 += static_cast<float>(y) * size;
    if (nodes_[node].child[q] == 0) return density;
    node = nodes_[node].child[q];
  }
}

float DirectionalTree::pdf(const Vec3f& d) const {
  const std::array<float, 2> s = direction_to_square(d);
  return square_pdf(s[0], s[1]) / (4.0f * kPi);
}

}  // namespace landsim::renderer
