#pragma once
// Small 3-vector used across landsim. Double precision for georeferenced coordinates,
// float for geometry handed to Embree (see docs/ARCHITECTURE.md, "Coordinates and units").
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

}  // namespace landsim
