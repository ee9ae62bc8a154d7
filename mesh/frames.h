// Rotation-minimizing frames along a polyline by the double reflection method:
// W. Wang, B. Jüttler, D. Zheng, Y. Liu, "Computation of rotation minimizing frames",
// ACM Transactions on Graphics 27(1), 2008, Algorithm 1 (section 4). Sweeping a tube with these
// frames keeps it free of twist, which the turtle's own frame (rolled by `/` and `$`) is not.
#pragma once

#include <vector>

#include "core/vec3.h"

namespace ramus::mesh {

// Unit tangents at the points: the normalized mean of the adjacent segment directions; at a
// reversal (mean near zero) the incoming direction. Consecutive points must differ.
std::vector<Vec3> polyline_tangents(const std::vector<Vec3>& points);

// Unit tangents over a window: at point i the direction of the chord between the points
// `half[i]` of arc length before and after it (clamped to the ends). A tube of radius r cannot
// turn within less than r, so a ring takes the direction of the path over its radius: kinks of
// the path shorter than that (the nodes of a reconstructed trunk a fifth of its radius off its
// axis, 20 cm apart) shear the tube instead of tilting its rings against each other. Where the
// window lies within the two segments at i this is polyline_tangents' bisector (the same
// arithmetic: the same bits); where the chord vanishes (the path comes back on itself within
// the window), polyline_tangents' tangent.
std::vector<Vec3> windowed_tangents(const std::vector<Vec3>& points,
                                    const std::vector<double>& half);

// Reference vectors r_i (unit, perpendicular to t_i) starting from `r0` (projected onto the
// plane normal to t_0; an arbitrary perpendicular when r0 is parallel to t_0).
std::vector<Vec3> rotation_minimizing_frames(const std::vector<Vec3>& points,
                                             const std::vector<Vec3>& tangents, const Vec3& r0);

// Some unit vector perpendicular to unit t.
Vec3 any_perpendicular(const Vec3& t);

}  // namespace ramus::mesh
