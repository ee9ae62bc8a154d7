// Least-squares line fitting of a branch (thesis draft section 4.2.3, Eq. 4.8-4.10) and its
// radius (section 4.2.4, Alg. 5).
#pragma once

#include <cstdint>
#include <vector>

#include "core/vec3.h"

namespace ramus::flood {

struct LineFit {
  Vec3 direction{0, 0, 1};  // unit d of x = x0 + d t
  int iterations = 0;
};

// Fits x = x0 + d t (Eq. 4.8) to the points by minimizing E = sum |d t_i - (x_i - x0)|^2
// (Eq. 4.10). For fixed t_i the 3m equations of Eq. 4.9 give d = (U^T U)^-1 U^T b in closed form;
// t_i = (x_i - x0) . d is then re-estimated, and the two steps alternate from `start` until d
// stops turning. The result points to the side where the points lie. A set whose points all sit
// on x0 returns `start`.
LineFit fit_line_through(const Vec3& x0, const std::vector<Vec3>& points, const Vec3& start);

// Alg. 5: R = factor x D_avg, D_avg the mean distance of the points to the line x0 + d t.
// The thesis uses factor 2 (a solid, uniformly filled branch). 0 for no points.
double line_radius(const Vec3& x0, const Vec3& direction, const std::vector<Vec3>& points,
                   double factor = 2.0);

}  // namespace ramus::flood
