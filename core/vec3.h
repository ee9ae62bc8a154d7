// Small 3D vector used by the types every stage shares (Skeleton, PointCloud).
// Kept free of Eigen so that the embeddable runtime and the file readers stay light;
// numeric code that needs linear algebra converts at its boundary.
#pragma once

#include <cmath>

namespace ramus {

template <typename T>
struct Vec3T {
  T x = 0, y = 0, z = 0;

  constexpr Vec3T() = default;
  constexpr Vec3T(T x_, T y_, T z_) : x(x_), y(y_), z(z_) {}
  template <typename U>
  constexpr explicit Vec3T(const Vec3T<U>& o) : x(T(o.x)), y(T(o.y)), z(T(o.z)) {}

  constexpr T& operator[](int i) { return i == 0 ? x : (i == 1 ? y : z); }
  constexpr T operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }

  constexpr Vec3T operator+(const Vec3T& o) const { return {x + o.x, y + o.y, z + o.z}; }
  constexpr Vec3T operator-(const Vec3T& o) const { return {x - o.x, y - o.y, z - o.z}; }
  constexpr Vec3T operator-() const { return {-x, -y, -z}; }
  constexpr Vec3T operator*(T s) const { return {x * s, y * s, z * s}; }
  constexpr Vec3T operator/(T s) const { return {x / s, y / s, z / s}; }
  constexpr Vec3T& operator+=(const Vec3T& o) { x += o.x; y += o.y; z += o.z; return *this; }
  constexpr Vec3T& operator-=(const Vec3T& o) { x -= o.x; y -= o.y; z -= o.z; return *this; }
  constexpr Vec3T& operator*=(T s) { x *= s; y *= s; z *= s; return *this; }
  constexpr bool operator==(const Vec3T& o) const = default;
};

template <typename T>
constexpr Vec3T<T> operator*(T s, const Vec3T<T>& v) { return v * s; }
template <typename T>
constexpr T dot(const Vec3T<T>& a, const Vec3T<T>& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
template <typename T>
constexpr Vec3T<T> cross(const Vec3T<T>& a, const Vec3T<T>& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
template <typename T>
T length(const Vec3T<T>& v) { return std::sqrt(dot(v, v)); }
template <typename T>
T distance(const Vec3T<T>& a, const Vec3T<T>& b) { return length(a - b); }
// Unit vector along v; returns `fallback` when v is (nearly) zero so callers never see NaN.
template <typename T>
Vec3T<T> normalized(const Vec3T<T>& v, const Vec3T<T>& fallback = {0, 0, 1}) {
  T len = length(v);
  return len > T(1e-30) ? v / len : fallback;
}
template <typename T>
bool is_finite(const Vec3T<T>& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

using Vec3 = Vec3T<double>;
using Vec3f = Vec3T<float>;

}  // namespace ramus
