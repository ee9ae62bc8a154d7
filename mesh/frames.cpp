#include "mesh/frames.h"

#include <algorithm>
#include <cmath>

namespace ramus::mesh {

Vec3 any_perpendicular(const Vec3& t) {
  // Cross with the axis least aligned with t, so the result is never tiny.
  const Vec3 axis = std::abs(t.x) < 0.57   ? Vec3{1, 0, 0}
                    : std::abs(t.y) < 0.57 ? Vec3{0, 1, 0}
                                           : Vec3{0, 0, 1};
  return normalized(cross(t, axis), Vec3{1, 0, 0});
}

std::vector<Vec3> polyline_tangents(const std::vector<Vec3>& pts) {
  const std::size_t m = pts.size();
  std::vector<Vec3> t(m, Vec3{0, 0, 1});
  if (m < 2) return t;
  std::vector<Vec3> d(m - 1);
  for (std::size_t i = 0; i + 1 < m; ++i) d[i] = normalized(pts[i + 1] - pts[i]);
  t[0] = d[0];
  t[m - 1] = d[m - 2];
  for (std::size_t i = 1; i + 1 < m; ++i) {
    const Vec3 sum = d[i - 1] + d[i];
    t[i] = length(sum) > 1e-6 ? normalized(sum) : d[i - 1];
  }
  return t;
}

std::vector<Vec3> windowed_tangents(const std::vector<Vec3>& pts, const std::vector<double>& half) {
  const std::vector<Vec3> t = polyline_tangents(pts);
  const std::size_t m = pts.size();
  if (m < 3 || half.size() != m) return t;
  std::vector<double> s(m, 0.0);  // arc length at each point
  for (std::size_t i = 1; i < m; ++i) s[i] = s[i - 1] + distance(pts[i], pts[i - 1]);
  // The point at arc length q (clamped to the polyline).
  auto at = [&](double q) {
    if (!(q > 0)) return pts.front();
    if (!(q < s.back())) return pts.back();
    const std::size_t k = std::size_t(std::upper_bound(s.begin(), s.end(), q) - s.begin());
    const double len = s[k] - s[k - 1];
    return len > 0 ? pts[k - 1] + (pts[k] - pts[k - 1]) * ((q - s[k - 1]) / len) : pts[k];
  };
  std::vector<Vec3> out = t;
  for (std::size_t i = 0; i < m; ++i) {
    // Near an end the window shrinks to stay centred on its point (clamped, it would lean with
    // the last kink); the end points take the chord of the window ahead of or behind them.
    const double h = i == 0 || i + 1 == m ? half[i] : std::min({half[i], s[i], s.back() - s[i]});
    const bool before = i == 0 || s[i] - s[i - 1] >= h;
    const bool after = i + 1 == m || s[i + 1] - s[i] >= h;
    if (!(h > 0) || (before && after)) continue;
    const Vec3 chord = at(s[i] + h) - at(s[i] - h);
    if (length(chord) > 1e-9 * std::max(h, 1e-300)) out[i] = normalized(chord, t[i]);
  }
  return out;
}

std::vector<Vec3> rotation_minimizing_frames(const std::vector<Vec3>& x, const std::vector<Vec3>& t,
                                             const Vec3& r0) {
  const std::size_t m = x.size();
  std::vector<Vec3> r(m);
  if (m == 0) return r;
  Vec3 start = r0 - t[0] * dot(r0, t[0]);
  r[0] = length(start) > 1e-9 ? normalized(start) : any_perpendicular(t[0]);
  for (std::size_t i = 0; i + 1 < m; ++i) {
    // Reflection R1 in the bisecting plane of x_i and x_{i+1} (Wang et al. 2008, Alg. 1).
    const Vec3 v1 = x[i + 1] - x[i];
    const double c1 = dot(v1, v1);
    Vec3 rl = r[i], tl = t[i];
    if (c1 > 0) {
      rl = r[i] - v1 * (2.0 / c1 * dot(v1, r[i]));
      tl = t[i] - v1 * (2.0 / c1 * dot(v1, t[i]));
    }
    // Reflection R2 maps the reflected tangent onto t_{i+1}.
    const Vec3 v2 = t[i + 1] - tl;
    const double c2 = dot(v2, v2);
    Vec3 next = c2 > 1e-24 ? rl - v2 * (2.0 / c2 * dot(v2, rl)) : rl;
    // Re-orthonormalize against rounding drift over very long chains.
    next = next - t[i + 1] * dot(next, t[i + 1]);
    r[i + 1] = length(next) > 1e-9 ? normalized(next) : any_perpendicular(t[i + 1]);
  }
  return r;
}

}  // namespace ramus::mesh
