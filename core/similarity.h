// Small transforms: a column-major 4x4 matrix (the layout glTF stores), a unit quaternion and a
// translation-rotation-uniform-scale triple (TRS). Every transform that joins pieces is a
// similarity (Burkus et al. 2017, section 4.2), so a TRS with one scale factor holds it exactly
// and writes straight into a glTF node. In core/ because the pieces back end and the placed-pieces
// stream of an .rmb (formats/rmb/rmb_piece_stream.h, expanded by the runtime too) compose poses
// with this one code, which is what makes their bone matrices agree bit for bit.
#pragma once

#include <array>

#include "core/vec3.h"

namespace ramus {

// Column-major: m[col * 4 + row]; the translation is m[12], m[13], m[14].
struct Mat4 {
  std::array<double, 16> m{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};

  static Mat4 identity() { return Mat4{}; }
  double& operator()(int row, int col) { return m[col * 4 + row]; }
  double operator()(int row, int col) const { return m[col * 4 + row]; }
  Mat4 operator*(const Mat4& o) const;
  Vec3 point(const Vec3& p) const;      // M (p, 1)
  Vec3 direction(const Vec3& d) const;  // M (d, 0)
  // Transforms a surface normal: the inverse transpose of the linear part, renormalized.
  Vec3 normal(const Vec3& n) const;
  Mat4 inverse() const;  // general 4x4 inverse (affine input in practice)
};

// Unit quaternion w + xi + yj + zk.
struct Quat {
  double w = 1, x = 0, y = 0, z = 0;

  static Quat axis_angle(const Vec3& axis, double radians);  // axis need not be unit
  // The shortest rotation taking unit vector a to unit vector b.
  static Quat between(const Vec3& a, const Vec3& b);
  Quat operator*(const Quat& o) const;
  Vec3 rotate(const Vec3& v) const;
  Quat normalized() const;
  Quat conjugate() const { return {w, -x, -y, -z}; }
  bool operator==(const Quat&) const = default;
};

// Normalized linear interpolation between two rotations along the short arc.
Quat nlerp(const Quat& a, const Quat& b, double t);

// x -> t + s * (r x): a similarity (glTF node order T * R * S with a uniform S).
struct Trs {
  Vec3 t{0, 0, 0};
  Quat r{};
  double s = 1.0;

  Mat4 matrix() const;
  Vec3 point(const Vec3& p) const { return t + r.rotate(p) * s; }
  Trs operator*(const Trs& o) const;  // (this * o)(x) = this(o(x))
  Trs inverse() const;
  bool operator==(const Trs&) const = default;
};

}  // namespace ramus
