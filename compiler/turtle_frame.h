// The turtle's frame (ABOP ch. 1.5 and 2.2): heading H, left L, up U = H x L, and the turns the
// turtle symbols make of it. The turtle (turtle.cpp) moves one; inference writes turtle strings
// that must reach measured directions, and follows the same frame, with the same arithmetic,
// to compute each turn from where the turtle will actually be.
#pragma once

#include "core/vec3.h"

namespace ramus {

struct TurtleFrame {
  Vec3 h{0, 0, 1}, l{-1, 0, 0}, u{0, -1, 0};

  // Keeps the frame orthonormal and right-handed (U = H x L) against rounding drift; the turtle
  // calls it after every turn (`+ - & ^ \ / |`).
  void orthonormalize();
  // `$` (ABOP ch. 2): L = V x H / |V x H| with V opposite to gravity, U = H x L; a vertical
  // heading leaves the frame as it is.
  void level();
  // ABOP ch. 2.2: after each segment the heading bends towards the tropism vector T by
  // alpha = e |H x T| (radians), about the axis H x T.
  void bend(const Vec3& tropism, double elasticity);
};

// Rotation of the pair (a, b) in their plane: a' = a cos + b sin, b' = b cos - a sin (degrees).
// `+(x)` is rotate_pair(h, l, x), `&(x)` rotate_pair(h, u, -x), `/(x)` rotate_pair(l, u, -x).
void rotate_pair(Vec3& a, Vec3& b, double degrees);

}  // namespace ramus
