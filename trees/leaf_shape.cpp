#include "trees/leaf_shape.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <functional>
#include <numbers>

namespace landsim::trees {
namespace {

constexpr float kPi = std::numbers::pi_v<float>;

using HalfWidth = std::function<float(float)>;

// A blade symmetric about the midrib: rows along y, a left and right vertex per row, the
// base and tip collapsed to one vertex; triangulated as a strip (valid for any y-monotone
// outline, lobed or not).
LeafTemplate strip_blade(const HalfWidth& w, int rows) {
  LeafTemplate t;
  t.vertices.push_back({0.0f, 0.0f, 0.0f});
  for (int i = 1; i < rows; ++i) {
    const float y = static_cast<float>(i) / static_cast<float>(rows);
    t.vertices.push_back({-w(y), y, 0.0f});
    t.vertices.push_back({w(y), y, 0.0f});
  }
  t.vertices.push_back({0.0f, 1.0f, 0.0f});
  const auto left = [](int i) { return static_cast<std::uint32_t>(2 * i - 1); };
  const auto right = [](int i) { return static_cast<std::uint32_t>(2 * i); };
  t.indices.insert(t.indices.end(), {0u, right(1), left(1)});
  for (int i = 1; i + 1 < rows; ++i) {
    t.indices.insert(t.indices.end(), {left(i), right(i), right(i + 1)});
    t.indices.insert(t.indices.end(), {left(i), right(i + 1), left(i + 1)});
  }
  const auto tip = static_cast<std::uint32_t>(t.vertices.size() - 1);
  t.indices.insert(t.indices.end(), {left(rows - 1), right(rows - 1), tip});
  return t;
}

// A star-shaped outline r(theta) about `centre`, triangulated as a fan.
LeafTemplate radial_blade(const std::function<float(float)>& r, Vec3f centre, int points) {
  LeafTemplate t;
  t.vertices.push_back(centre);
  for (int i = 0; i < points; ++i) {
    const float a = 2.0f * kPi * static_cast<float>(i) / static_cast<float>(points);
    t.vertices.push_back(centre + Vec3f{r(a) * std::cos(a), r(a) * std::sin(a), 0.0f});
  }
  for (int i = 0; i < points; ++i) {
    const auto a = static_cast<std::uint32_t>(1 + i);
    const auto b = static_cast<std::uint32_t>(1 + (i + 1) % points);
    t.indices.insert(t.indices.end(), {0u, a, b});
  }
  return t;
}

// Convex oval polygon of n + 2 vertices fanned from the first: exactly n triangles.
LeafTemplate disc(int n) {
  LeafTemplate t;
  const int count = n + 2;
  for (int i = 0; i < count; ++i) {
    // Start at the base (angle -90 degrees) so the leaf grows from its stalk.
    const float a = -0.5f * kPi + 2.0f * kPi * static_cast<float>(i) / static_cast<float>(count);
    t.vertices.push_back({0.5f * std::cos(a), 0.5f + 0.5f * std::sin(a), 0.0f});
  }
  for (int i = 1; i + 1 < count; ++i) {
    t.indices.insert(t.indices.end(),
                     {0u, static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(i + 1)});
  }
  return t;
}

LeafTemplate leaflets3() {
  LeafTemplate t;
  for (float angle : {-0.7f, 0.0f, 0.7f}) {
    const LeafTemplate one = disc(6);
    const auto offset = static_cast<std::uint32_t>(t.vertices.size());
    for (Vec3f v : one.vertices) {
      // Each leaflet half as long, rotated about the common stalk point.
      v = v * 0.55f;
      const float c = std::cos(angle), s = std::sin(angle);
      t.vertices.push_back({c * v.x - s * v.y, s * v.x + c * v.y, 0.0f});
    }
    for (std::uint32_t i : one.indices) t.indices.push_back(offset + i);
  }
  return t;
}

LeafTemplate icosahedron() {
  LeafTemplate t;
  const float p = (1.0f + std::sqrt(5.0f)) / 2.0f;
  const std::array<Vec3f, 12> v{{{-1, p, 0},
                                 {1, p, 0},
                                 {-1, -p, 0},
                                 {1, -p, 0},
                                 {0, -1, p},
                                 {0, 1, p},
                                 {0, -1, -p},
                                 {0, 1, -p},
                                 {p, 0, -1},
                                 {p, 0, 1},
                                 {-p, 0, -1},
                                 {-p, 0, 1}}};
  const float scale = 0.5f / length(v[0]);
  for (const Vec3f& x : v) t.vertices.push_back(Vec3f{0.0f, 0.5f, 0.0f} + x * scale);
  t.indices = {0, 11, 5,  0, 5,  1, 0, 1, 7, 0, 7,  10, 0, 10, 11, 1, 5, 9, 5, 11,
               4, 11, 10, 2, 10, 7, 6, 7, 1, 8, 3,  9,  4, 3,  4,  2, 3, 2, 6, 3,
               6, 8,  3,  8, 9,  4, 9, 5, 2, 4, 11, 6,  2, 10, 8,  6, 7, 9, 8, 1};
  return t;
}

// Scales and shifts a template so that x spans [-0.5, 0.5] and y [0, 1].
void normalise(LeafTemplate& t) {
  float lo_x = 1e9f, hi_x = -1e9f, lo_y = 1e9f, hi_y = -1e9f;
  for (const Vec3f& v : t.vertices) {
    lo_x = std::min(lo_x, v.x);
    hi_x = std::max(hi_x, v.x);
    lo_y = std::min(lo_y, v.y);
    hi_y = std::max(hi_y, v.y);
  }
  const float sx = 1.0f / (hi_x - lo_x), sy = 1.0f / (hi_y - lo_y);
  const float cx = 0.5f * (lo_x + hi_x);
  for (Vec3f& v : t.vertices) v = {(v.x - cx) * sx, (v.y - lo_y) * sy, v.z * sx};
}

bool inside_triangle(float px, float py, const Vec3f& a, const Vec3f& b, const Vec3f& c) {
  const auto side = [&](const Vec3f& u, const Vec3f& v) {
    return (v.x - u.x) * (py - u.y) - (v.y - u.y) * (px - u.x);
  };
  const float d1 = side(a, b), d2 = side(b, c), d3 = side(c, a);
  const bool neg = d1 < 0 || d2 < 0 || d3<0, pos = d1> 0 || d2 > 0 || d3 > 0;
  return !(neg && pos);
}

// Area the blade covers seen along its normal: sampled on a grid, so that overlapping parts
// (leaflets) count once.
float covered_area(const LeafTemplate& t) {
  constexpr int kGrid = 64;
  int hits = 0;
  for (int j = 0; j < kGrid; ++j) {
    for (int i = 0; i < kGrid; ++i) {
      const float x = -0.5f + (static_cast<float>(i) + 0.5f) / kGrid;
      const float y = (static_cast<float>(j) + 0.5f) / kGrid;
      for (std::size_t k = 0; k + 2 < t.indices.size(); k += 3) {
        if (inside_triangle(x, y, t.vertices[t.indices[k]], t.vertices[t.indices[k + 1]],
                            t.vertices[t.indices[k + 2]])) {
          ++hits;
          break;
        }
      }
    }
  }
  return static_cast<float>(hits) / (kGrid * kGrid);
}

}  // namespace

LeafTemplate make_leaf_template(const LeafShape& shape) {
  LeafTemplate t;
  switch (shape.kind) {
    case LeafShapeKind::oval:
      t = strip_blade(
          [](float y) {
            return 0.5f * std::sqrt(std::max(0.0f, 1.0f - (2 * y - 1) * (2 * y - 1)));
          },
          4);
      break;
    case LeafShapeKind::triangle:
      t.vertices = {{-0.5f, 0.0f, 0.0f}, {0.5f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}};
      t.indices = {0, 1, 2};
      break;
    case LeafShapeKind::oak3:
      t = strip_blade(
          [](float y) {
            const float lobes = std::sin(3.0f * kPi * y);
            return 0.5f * std::pow(std::sin(kPi * y), 0.6f) * (0.6f + 0.4f * lobes * lobes);
          },
          12);
      break;
    case LeafShapeKind::maple3:
    case LeafShapeKind::maple5: {
      const float k = shape.kind == LeafShapeKind::maple3 ? 3.0f : 5.0f;
      t = radial_blade(
          [k](float a) {
            const float lobe =
                0.55f + 0.45f * std::pow(std::abs(std::cos(0.5f * k * (a - 0.5f * kPi))), 3.0f);
            const float notch =
                1.0f - 0.6f * std::pow(std::max(0.0f, -std::sin(a)), 8.0f);  // at the stalk
            return 0.5f * lobe * notch;
          },
          Vec3f{0.0f, 0.0f, 0.0f}, shape.kind == LeafShapeKind::maple3 ? 18 : 30);
      break;
    }
    case LeafShapeKind::leaflets3:
      t = leaflets3();
      break;
    case LeafShapeKind::palm: {
      t = strip_blade(
          [](float y) {
            return 0.5f * std::sqrt(std::max(0.0f, 1.0f - (2 * y - 1) * (2 * y - 1)));
          },
          6);
      for (Vec3f& v : t.vertices) v.z = std::abs(v.x) * 0.58f;  // 30 degrees fold along the midrib
      break;
    }
    case LeafShapeKind::sphere:
      t = icosahedron();
      break;
    case LeafShapeKind::disc_n:
      t = disc(std::max(1, shape.triangles));
      break;
  }
  normalise(t);
  t.area = shape.kind == LeafShapeKind::sphere ? 0.25f * kPi : covered_area(t);
  return t;
}

bool parse_leaf_shape(const std::string& text, LeafShape& out) {
  static const std::array<const char*, 8> kNames{"oval",   "triangle", "oak",  "maple3",
                                                 "maple5", "leaflets", "palm", "sphere"};
  for (std::size_t i = 0; i < kNames.size(); ++i) {
    if (text == kNames[i] || text == std::to_string(i)) {
      out = {static_cast<LeafShapeKind>(i), 6};
      return true;
    }
  }
  if (text == "disc") {
    out = {LeafShapeKind::oval, 6};
    return true;
  }
  if (text.size() > 4 && text.size() <= 6 && text.rfind("disc", 0) == 0 &&  // disc1..disc64
      std::all_of(text.begin() + 4, text.end(),
                  [](unsigned char c) { return std::isdigit(c) != 0; })) {
    const int n = std::stoi(text.substr(4));
    if (n < 1 || n > 64) return false;
    out = {LeafShapeKind::disc_n, n};
    return true;
  }
  return false;
}

}  // namespace landsim::trees
