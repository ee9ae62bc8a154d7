// Similarity transforms (similarity.h).
#include "core/similarity.h"

#include <cmath>

namespace ramus {

Mat4 Mat4::operator*(const Mat4& o) const {
  Mat4 r;
  for (int c = 0; c < 4; ++c) {
    for (int row = 0; row < 4; ++row) {
      double s = 0;
      for (int k = 0; k < 4; ++k) s += (*this)(row, k) * o(k, c);
      r(row, c) = s;
    }
  }
  return r;
}

Vec3 Mat4::point(const Vec3& p) const {
  const Mat4& a = *this;
  return {a(0, 0) * p.x + a(0, 1) * p.y + a(0, 2) * p.z + a(0, 3),
          a(1, 0) * p.x + a(1, 1) * p.y + a(1, 2) * p.z + a(1, 3),
          a(2, 0) * p.x + a(2, 1) * p.y + a(2, 2) * p.z + a(2, 3)};
}

Vec3 Mat4::direction(const Vec3& d) const {
  const Mat4& a = *this;
  return {a(0, 0) * d.x + a(0, 1) * d.y + a(0, 2) * d.z,
          a(1, 0) * d.x + a(1, 1) * d.y + a(1, 2) * d.z,
          a(2, 0) * d.x + a(2, 1) * d.y + a(2, 2) * d.z};
}

Vec3 Mat4::normal(const Vec3& n) const {
  // The cofactor matrix of the linear part is det * inverse transpose: the same direction
  // without dividing by a determinant that may be tiny.
  const Mat4& a = *this;
  auto c = [&](int r, int col) {
    int r0 = (r + 1) % 3, r1 = (r + 2) % 3, c0 = (col + 1) % 3, c1 = (col + 2) % 3;
    return a(r0, c0) * a(r1, c1) - a(r0, c1) * a(r1, c0);
  };
  Vec3 v{c(0, 0) * n.x + c(0, 1) * n.y + c(0, 2) * n.z,
         c(1, 0) * n.x + c(1, 1) * n.y + c(1, 2) * n.z,
         c(2, 0) * n.x + c(2, 1) * n.y + c(2, 2) * n.z};
  double det = a(0, 0) * c(0, 0) + a(0, 1) * c(0, 1) + a(0, 2) * c(0, 2);
  if (det < 0) v = -v;
  return normalized(v, n);
}

Mat4 Mat4::inverse() const {
  // Gauss-Jordan elimination with partial pivoting.
  double a[4][8];
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) {
      a[r][c] = (*this)(r, c);
      a[r][c + 4] = r == c ? 1.0 : 0.0;
    }
  }
  for (int c = 0; c < 4; ++c) {
    int p = c;
    for (int r = c + 1; r < 4; ++r) {
      if (std::abs(a[r][c]) > std::abs(a[p][c])) p = r;
    }
    if (p != c) {
      for (int k = 0; k < 8; ++k) std::swap(a[p][k], a[c][k]);
    }
    double d = a[c][c];
    if (d == 0) return Mat4{};  // singular: callers only invert similarities
    for (int k = 0; k < 8; ++k) a[c][k] /= d;
    for (int r = 0; r < 4; ++r) {
      if (r == c) continue;
      double f = a[r][c];
      if (f == 0) continue;
      for (int k = 0; k < 8; ++k) a[r][k] -= f * a[c][k];
    }
  }
  Mat4 r;
  for (int row = 0; row < 4; ++row) {
    for (int c = 0; c < 4; ++c) r(row, c) = a[row][c + 4];
  }
  return r;
}

Quat Quat::axis_angle(const Vec3& axis, double radians) {
  Vec3 u = ramus::normalized(axis);
  double s = std::sin(radians / 2);
  return {std::cos(radians / 2), u.x * s, u.y * s, u.z * s};
}

Quat Quat::between(const Vec3& a, const Vec3& b) {
  double d = dot(a, b);
  if (d < -1 + 1e-12) {
    // Opposite: any axis perpendicular to a.
    Vec3 axis = cross(a, Vec3{1, 0, 0});
    if (length(axis) < 1e-6) axis = cross(a, Vec3{0, 1, 0});
    return axis_angle(axis, M_PI);
  }
  Vec3 c = cross(a, b);
  return Quat{1 + d, c.x, c.y, c.z}.normalized();
}

Quat Quat::operator*(const Quat& o) const {
  return {w * o.w - x * o.x - y * o.y - z * o.z, w * o.x + x * o.w + y * o.z - z * o.y,
          w * o.y - x * o.z + y * o.w + z * o.x, w * o.z + x * o.y - y * o.x + z * o.w};
}

Vec3 Quat::rotate(const Vec3& v) const {
  Vec3 q{x, y, z};
  Vec3 t = cross(q, v) * 2.0;
  return v + t * w + cross(q, t);
}

Quat Quat::normalized() const {
  double n = std::sqrt(w * w + x * x + y * y + z * z);
  if (n < 1e-300) return {};
  return {w / n, x / n, y / n, z / n};
}

Quat nlerp(const Quat& a, const Quat& b, double t) {
  double d = a.w * b.w + a.x * b.x + a.y * b.y + a.z * b.z;
  double s = d < 0 ? -1.0 : 1.0;
  return Quat{a.w + (s * b.w - a.w) * t, a.x + (s * b.x - a.x) * t, a.y + (s * b.y - a.y) * t,
              a.z + (s * b.z - a.z) * t}
      .normalized();
}

Mat4 Trs::matrix() const {
  Mat4 m;
  Vec3 cx = r.rotate({1, 0, 0}) * s, cy = r.rotate({0, 1, 0}) * s, cz = r.rotate({0, 0, 1}) * s;
  m.m = {cx.x, cx.y, cx.z, 0, cy.x, cy.y, cy.z, 0, cz.x, cz.y, cz.z, 0, t.x, t.y, t.z, 1};
  return m;
}

Trs Trs::operator*(const Trs& o) const {
  // this(o(x)) = t + s R (o.t + o.s o.R x)
  return {t + r.rotate(o.t) * s, (r * o.r).normalized(), s * o.s};
}

Trs Trs::inverse() const {
  Quat ri = r.conjugate();
  return {-(ri.rotate(t) / s), ri, 1.0 / s};
}

}  // namespace ramus
