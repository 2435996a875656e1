#pragma once
// Small 3-vector used across landsim. Double precision for georeferenced coordinates,
// float for geometry handed to Embree (see docs/ARCHITECTURE.md, "Coordinates").
#include <cmath>

namespace landsim {

template <typename T>
struct Vec3T {
  T x{}, y{}, z{};

  constexpr Vec3T() = default;
  constexpr Vec3T(T x_, T y_, T z_) : x(x_), y(y_), z(z_) {}
  template <typename U>
  constexpr explicit Vec3T(const Vec3T<U>& o)
      : x(static_cast<T>(o.x)), y(static_cast<T>(o.y)), z(static_cast<T>(o.z)) {}

  constexpr T operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
  constexpr Vec3T operator-() const { return {-x, -y, -z}; }
  constexpr Vec3T& operator+=(const Vec3T& o) {
    x += o.x;
    y += o.y;
    z += o.z;
    return *this;
  }
  constexpr Vec3T& operator-=(const Vec3T& o) {
    x -= o.x;
    y -= o.y;
    z -= o.z;
    return *this;
  }
  constexpr Vec3T& operator*=(T s) {
    x *= s;
    y *= s;
    z *= s;
    return *this;
  }
  friend constexpr Vec3T operator+(Vec3T a, const Vec3T& b) { return a += b; }
  friend constexpr Vec3T operator-(const Vec3T& a, const Vec3T& b) {
    return {a.x - b.x, a.y - b.y, a.z - b.z};
  }
  friend constexpr Vec3T operator*(Vec3T a, T s) { return a *= s; }
  friend constexpr Vec3T operator*(T s, Vec3T a) { return a *= s; }
  friend constexpr Vec3T operator*(const Vec3T& a, const Vec3T& b) {
    return {a.x * b.x, a.y * b.y, a.z * b.z};
  }
  friend constexpr Vec3T operator/(const Vec3T& a, T s) { return {a.x / s, a.y / s, a.z / s}; }
  friend constexpr bool operator==(const Vec3T&, const Vec3T&) = default;
};

using Vec3 = Vec3T<double>;
using Vec3f = Vec3T<float>;

template <typename T>
constexpr T dot(const Vec3T<T>& a, const Vec3T<T>& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
template <typename T>
constexpr Vec3T<T> cross(const Vec3T<T>& a, const Vec3T<T>& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
template <typename T>
T length(const Vec3T<T>& a) {
  return std::sqrt(dot(a, a));
}
template <typename T>
Vec3T<T> normalize(const Vec3T<T>& a) {
  return a / length(a);
}
template <typename T>
constexpr T max_component(const Vec3T<T>& a) {
  return a.x > a.y ? (a.x > a.z ? a.x : a.z) : (a.y > a.z ? a.y : a.z);
}

// Orthonormal basis around a unit normal (Duff et al. 2017, branchless), so that
// directions sampled about +z can be turned into world directions around n.
template <typename T>
void orthonormal_basis(const Vec3T<T>& n, Vec3T<T>& t, Vec3T<T>& b) {
  const T sign = std::copysign(T(1), n.z);
  const T a = T(-1) / (sign + n.z);
  const T c = n.x * n.y * a;
  t = {T(1) + sign * n.x * n.x * a, sign * c, -sign * n.x};
  b = {c, sign + n.y * n.y * a, -n.y};
}

// Rodrigues' rotation of v about the unit axis by `angle` radians.
inline Vec3 rotate_about(const Vec3& v, const Vec3& axis, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return v * c + cross(axis, v) * s + axis * (dot(axis, v) * (1.0 - c));
}

// The unit vector perpendicular to the unit `axis` nearest to `near` (a fixed fallback when
// `near` is along the axis): for carrying a frame along a curve without twisting it.
inline Vec3 perpendicular_near(const Vec3& axis, const Vec3& near) {
  Vec3 f = near - axis * dot(near, axis);
  if (length(f) < 1e-9)
    f = std::abs(axis.x) < 0.9 ? Vec3{1, 0, 0} - axis * axis.x : Vec3{0, 1, 0} - axis * axis.y;
  return normalize(f);
}

// Some unit vector perpendicular to the unit `axis` (horizontal unless the axis is near z).
inline Vec3 any_perpendicular(const Vec3& axis) {
  return normalize(cross(axis, std::abs(axis.z) < 0.9 ? Vec3{0, 0, 1} : Vec3{1, 0, 0}));
}

}  // namespace landsim
