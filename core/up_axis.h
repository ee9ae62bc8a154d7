// The one mapping from ramus's world (z up, as the turtle and the scans have it) to a y-up file:
// glTF 2.0 is always y up (spec 3.4: +Y up, +Z forward, right-handed); OBJ and PLY are y up on
// request (--up y). (x, y, z) -> (x, z, -y) is a rotation by -90 degrees about x, so handedness
// and the winding of triangles are kept. Every writer that turns a position, a normal, a
// rotation or a transform into y-up goes through these functions, so the convention lives here
// only.
#pragma once

#include <array>

#include "core/vec3.h"

namespace ramus::mesh {

enum class UpAxis { kZ, kY };

// A position, direction or normal.
template <typename T>
constexpr Vec3T<T> z_up_to_y_up(const Vec3T<T>& v) {
  return {v.x, v.z, -v.y};
}

// The inverse, for readers of y-up files (glTF; OBJ and PLY that say "up y"): (x, y, z) ->
// (x, -z, y), so z_up_to_y_up(y_up_to_z_up(v)) == v exactly.
template <typename T>
constexpr Vec3T<T> y_up_to_z_up(const Vec3T<T>& v) {
  return {v.x, -v.z, v.y};
}

// A unit quaternion (x, y, z, w) of the z-up world as the same rotation seen in y-up: its axis,
// the vector part, turns like any vector and its angle stays.
template <typename T>
constexpr std::array<T, 4> z_up_to_y_up_quaternion(T x, T y, T z, T w) {
  return {x, z, -y, w};
}

// A 4x4 transform in glTF's column-major order (m[col * 4 + row]) conjugated by the rotation:
// R * M * R^-1, so that it maps y-up points as M maps z-up ones.
template <typename T>
constexpr std::array<T, 16> z_up_to_y_up_matrix(const std::array<T, 16>& m) {
  // R sends axis 0 -> 0, 1 -> -2 (y becomes -z), 2 -> 1 (z becomes y):
  // (R M R^-1)[at(r)][at(c)] = sg(r) * sg(c) * M[r][c].
  // Row/column 3 (translation and projective parts) stays where it is.
  auto at = [](int i) { return i == 1 ? 2 : i == 2 ? 1 : i; };
  auto sg = [](int i) { return i == 1 ? -1 : 1; };
  std::array<T, 16> out{};
  for (int col = 0; col < 4; ++col) {
    for (int row = 0; row < 4; ++row) {
      out[at(col) * 4 + at(row)] = T(sg(col) * sg(row)) * m[col * 4 + row];
    }
  }
  return out;
}

}  // namespace ramus::mesh
