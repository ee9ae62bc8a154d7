#include "reconstruct/flood/line_fit.h"

#include <cmath>

namespace ramus::flood {

LineFit fit_line_through(const Vec3& x0, const std::vector<Vec3>& points, const Vec3& start) {
  LineFit fit;
  Vec3 d = normalized(start);
  fit.direction = d;
  for (int it = 0; it < 100; ++it) {
    // U is block-diagonal with t_i I (3 rows per point), b stacks (x_i - x0): U^T U = sum t_i^2,
    // U^T b = sum t_i (x_i - x0).
    double utu = 0;
    Vec3 utb{0, 0, 0};
    for (const Vec3& p : points) {
      const Vec3 b = p - x0;
      const double t = dot(b, d);
      utu += t * t;
      utb += b * t;
    }
    if (!(utu > 0)) break;
    const Vec3 next = normalized(utb / utu, d);
    fit.iterations = it + 1;
    const double change = length(next - d);
    d = next;
    if (change < 1e-10) break;
  }
  // Orient towards the points (the sign of d is free in Eq. 4.10).
  double side = 0;
  for (const Vec3& p : points) side += dot(p - x0, d);
  fit.direction = side < 0 ? -d : d;
  return fit;
}

double line_radius(const Vec3& x0, const Vec3& direction, const std::vector<Vec3>& points,
                   double factor) {
  if (points.empty()) return 0.0;
  double sum = 0;
  for (const Vec3& p : points) {
    const Vec3 b = p - x0;
    sum += length(b - direction * dot(b, direction));  // Alg. 5 line 3
  }
  return factor * sum / double(points.size());  // lines 5-6
}

}  // namespace ramus::flood
