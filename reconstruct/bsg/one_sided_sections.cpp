#include "reconstruct/bsg/one_sided_sections.h"

#include <tbb/parallel_for.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "reconstruct/bsg/bsg.h"
#include "reconstruct/bsg/circle_fit.h"

namespace ramus::bsg {

namespace {

double weight_at(const std::vector<double>& w, std::size_t i) { return w.empty() ? 1.0 : w[i]; }

// The radius of the branch at v from its own fits: the median of the nearest fitted radii up
// the chain (at most two, not past the fork where the branch leaves its stem) and down its
// heaviest chain (at most two), each within `steps` nodes. 0 when there is none.
double branch_radius(std::uint32_t v, const std::vector<std::uint32_t>& parent,
                     const std::vector<std::uint32_t>& main_child,
                     const std::vector<std::uint8_t>& fitted,
                     const std::vector<double>& fitted_radius, int steps = 10) {
  const std::size_t n = parent.size();
  double found[4];
  int m = 0, up = 0, down = 0;
  for (std::uint32_t a = v, k = 0; k < std::uint32_t(steps) && up < 2; ++k) {
    const std::uint32_t u = parent[a];
    // A side branch's chain starts at its fork: the stem above is another branch.
    if (u >= n || main_child[u] != a) break;
    a = u;
    if (fitted[a] && m < 4) found[m++] = fitted_radius[a], ++up;
  }
  for (std::uint32_t a = v, k = 0; k < std::uint32_t(steps) && down < 2; ++k) {
    a = main_child[a];
    if (a == kNone) break;
    if (fitted[a] && m < 4) found[m++] = fitted_radius[a], ++down;
  }
  if (m == 0) return 0;
  for (int i = 1; i < m; ++i) {  // insertion sort of at most four
    for (int j = i; j > 0 && found[j] < found[j - 1]; --j) std::swap(found[j], found[j - 1]);
  }
  return m % 2 ? found[m / 2] : 0.5 * (found[m / 2 - 1] + found[m / 2]);
}

// +1 when the arc of `pts` bends towards +normal (its centre lies on that side), -1 towards
// -normal, 0 when the bend is not clear: the weighted least-squares parabola
// v = a + b u + c u^2 (u, v the coordinates along `tangent` and `normal` from `m`) must have
// |c| at least three standard errors.
int concave_side(const std::vector<Eigen::Vector2d>& pts, const std::vector<double>& w,
                 const Eigen::Vector2d& m, const Eigen::Vector2d& tangent,
                 const Eigen::Vector2d& normal) {
  Eigen::Matrix3d ata = Eigen::Matrix3d::Zero();
  Eigen::Vector3d atb = Eigen::Vector3d::Zero();
  double sw = 0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const Eigen::Vector2d q = pts[i] - m;
    const double u = q.dot(tangent), v = q.dot(normal);
    const Eigen::Vector3d row(1, u, u * u);
    ata += w[i] * row * row.transpose();
    atb += w[i] * row * v;
    sw += w[i];
  }
  const Eigen::LDLT<Eigen::Matrix3d> ldlt(ata);
  const Eigen::Vector3d x = ldlt.solve(atb);
  if (!x.allFinite() || pts.size() < 4) return 0;
  double sse = 0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const Eigen::Vector2d q = pts[i] - m;
    const double u = q.dot(tangent), e = q.dot(normal) - (x(0) + x(1) * u + x(2) * u * u);
    sse += w[i] * e * e;
  }
  // Weights are point counts: the variance per unit weight, over the degrees of freedom.
  const double var = sse / std::max(sw - 3, 1.0);
  const Eigen::Matrix3d inv = ldlt.solve(Eigen::Matrix3d::Identity());
  const double se = std::sqrt(std::max(var * inv(2, 2), 0.0));
  if (!(std::abs(x(2)) >= 3 * se) || !(se >= 0)) return 0;
  return x(2) > 0 ? 1 : -1;
}

}  // namespace

KnownRadiusFit fit_circle_known_radius(const std::vector<Eigen::Vector2d>& pts,
                                       const std::vector<double>& weights, double r,
                                       const Eigen::Vector2d& start, double noise, int iterations) {
  KnownRadiusFit f;
  const std::size_t n = pts.size();
  if (n < 3 || !(r > 0)) return f;
  const double tau = 2.5 * std::max(noise, 1e-12);
  thread_local std::vector<double> e, len, near_e, ang;
  e.resize(n), len.resize(n);
  Eigen::Vector2d c = start;
  double scale = 0;
  auto residuals = [&] {
    near_e.clear();
    for (std::size_t i = 0; i < n; ++i) {
      len[i] = (pts[i] - c).norm();
      e[i] = len[i] - r;
      if (std::abs(e[i]) < 4 * tau) near_e.push_back(e[i]);
    }
    // The scale from the points near the circle, as in fit_circle: another branch's points in
    // the slab must not make themselves inliers.
    scale = std::max(near_e.empty() ? 4 * tau : robust_scale_in_place(near_e), noise);
  };
  residuals();
  for (int it = 0; it < iterations; ++it) {
    const bool tukey = it >= iterations / 3;
    Eigen::Matrix2d jtj = Eigen::Matrix2d::Zero();
    Eigen::Vector2d jte = Eigen::Vector2d::Zero();
    for (std::size_t i = 0; i < n; ++i) {
      const double rw = robust_weight(std::abs(e[i]) / scale, tukey) * weight_at(weights, i);
      if (rw <= 0 || !(len[i] > 0)) continue;
      const Eigen::Vector2d j = -(pts[i] - c) / len[i];
      jtj += rw * j * j.transpose();
      jte += rw * j * e[i];
    }
    jtj.diagonal() *= 1.0 + 1e-9;
    const Eigen::Vector2d step = jtj.ldlt().solve(-jte);
    if (!step.allFinite()) break;
    c += step;
    residuals();
    if (step.norm() < 1e-6 * r) break;
  }
  double win = 0, wall = 0;
  near_e.clear(), ang.clear();
  for (std::size_t i = 0; i < n; ++i) {
    const double w = weight_at(weights, i);
    wall += w;
    if (std::abs(e[i]) > 2.5 * scale) continue;
    win += w;
    near_e.push_back(e[i]);
    ang.push_back(std::atan2(pts[i].y() - c.y(), pts[i].x() - c.x()));
  }
  f.centre = c;
  f.residual = near_e.empty() ? scale : robust_scale_in_place(near_e);
  f.coverage = angular_coverage(ang);
  f.inlier_fraction = wall > 0 ? win / wall : 0;
  f.valid = c.allFinite();
  return f;
}

std::size_t fit_one_sided_sections(std::vector<Eigen::Vector3d>& pos,
                                   const std::vector<std::uint32_t>& parent,
                                   const std::vector<double>& hint,
                                   std::vector<std::uint8_t>& fitted,
                                   std::vector<double>& fitted_radius, const PointIndex& index,
                                   const std::vector<Eigen::Vector3d>& samples,
                                   const std::vector<double>& weight, const CentreLineParams& p,
                                   double noise) {
  const std::size_t n = pos.size();
  const auto ch = children_of(parent);
  // The heaviest child (largest subtree) continues a chain, as in the cross-sections.
  std::vector<std::size_t> size(n, 1);
  for (std::size_t v = n; v-- > 0;) {
    if (parent[v] < n) size[parent[v]] += size[v];
  }
  std::vector<std::uint32_t> main_child(n, kNone);
  for (std::uint32_t v = 0; v < n; ++v) {
    for (std::uint32_t c : ch[v]) {
      if (main_child[v] == kNone || size[c] > size[main_child[v]]) main_child[v] = c;
    }
  }
  const double thin = p.min_hint_spacings * p.spacing;
  const double min_arc = 60.0 * M_PI / 180;
  // The cross-section at v: the slab across the local direction (two nodes up to two down, as
  // centre_line.cpp's direction_at), `size` setting its reach and thickness as the radius hint
  // does for the cross-sections. Fills the per-thread pts / w; false when too few points.
  struct Frame {
    Eigen::Vector3d x, e1, e2;
  };
  thread_local std::vector<std::uint32_t> near;
  thread_local std::vector<Eigen::Vector2d> pts;
  thread_local std::vector<double> w;
  auto gather = [&](std::uint32_t v, double size, Frame& fr) {
    std::uint32_t a = v, b = v;
    for (int k = 0; k < 2; ++k) {
      if (parent[a] < n) a = parent[a];
      if (main_child[b] != kNone) b = main_child[b];
    }
    Eigen::Vector3d d = pos[b] - pos[a];
    if (!(d.norm() > 0)) return false;
    d.normalize();
    perpendicular_frame(d, fr.e1, fr.e2);
    fr.x = pos[v];
    // Reach and thickness as the cross-sections' first disc (centre_line.cpp, fit_slab).
    const double reach = std::max(2.5 * size, 5 * p.spacing);
    const double half = std::max(0.3 * size, 1.5 * p.spacing);
    gather_slab(fr.x, d, fr.e1, fr.e2, reach, half, index, samples, weight, near, pts, w);
    if (pts.size() < 8) return false;
    thin_slab(pts, w, p.max_slab_points);
    return true;
  };
  // The arc's concave side, from the sign of its curvature: a parabola v = a + b u + c u^2
  // across its chord (u along the major principal axis, v along the minor one). The mirror
  // circle on the convex side fits an arc of 60-90 degrees almost as well (residuals within
  // 10 % at 5 mm noise on a 7 cm limb), so the side must come from the bend, and the bend must
  // be clear: |c| at least three standard errors. Returns the side (0: unclear), the arc's
  // centroid and normal.
  auto bend = [&](Eigen::Vector2d& m, Eigen::Vector2d& normal) {
    double sw = 0;
    m.setZero();
    for (std::size_t i = 0; i < pts.size(); ++i) sw += w[i], m += w[i] * pts[i];
    m /= sw;
    Eigen::Matrix2d cov = Eigen::Matrix2d::Zero();
    for (std::size_t i = 0; i < pts.size(); ++i)
      cov += w[i] * (pts[i] - m) * (pts[i] - m).transpose();
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> es(cov);
    normal = es.eigenvectors().col(0);
    return concave_side(pts, w, m, es.eigenvectors().col(1), normal);
  };
  // The radius of every node: its branch's fits (branch_radius); where the branch has none, the
  // median of the free circle fits of its chain's one-sided arcs (at least three of them, each
  // clearly bent, 60 degrees or more, within the residual and inlier limits; Livny 4.3 and
  // TreeQSM take radii from the points where they can), at most the nearest fitted ancestor's.
  std::vector<double> r_of(n, 0.0), free_r(n, 0.0);
  std::vector<std::uint8_t> candidate(n, 0);
  for (std::uint32_t v = 0; v < n; ++v) {
    if (fitted[v] || ch[v].size() > 1 || hint[v] < thin) continue;
    candidate[v] = 1;
    r_of[v] = branch_radius(v, parent, main_child, fitted, fitted_radius);
  }
  tbb::parallel_for(std::size_t(0), n, [&](std::size_t vi) {
    const std::uint32_t v = std::uint32_t(vi);
    if (!candidate[v] || r_of[v] > 0) return;
    Frame fr;
    // Allometric hints are about half the fitted radii on thick_oak's limbs: the slab is sized
    // for twice the hint.
    if (!gather(v, 2 * hint[v], fr)) return;
    Eigen::Vector2d m, normal;
    const int side = bend(m, normal);
    if (side == 0) return;
    const CircleFit f = fit_circle(pts, w, noise);
    if (!f.valid || (f.centre - m).dot(normal) * side <= 0) return;
    if (f.coverage >= min_arc && f.inlier_fraction >= p.min_inliers &&
        f.residual <= p.max_residual * f.radius + noise && f.radius >= p.spacing &&
        f.radius <= p.max_hint_factor * hint[v])
      free_r[v] = f.radius;
  });
  {
    std::vector<double> radii;
    std::vector<std::uint32_t> chain;
    for (std::uint32_t s = 0; s < n; ++s) {
      if (parent[s] < n && ch[parent[s]].size() == 1) continue;  // not a chain start
      chain.clear(), radii.clear();
      for (std::uint32_t v = s;; v = ch[v][0]) {
        chain.push_back(v);
        if (free_r[v] > 0) radii.push_back(free_r[v]);
        if (ch[v].size() != 1) break;
      }
      if (radii.size() < 3) continue;
      std::nth_element(radii.begin(), radii.begin() + std::ptrdiff_t(radii.size() / 2),
                       radii.end());
      double r = radii[radii.size() / 2];
      for (std::uint32_t u = parent[s]; u < n; u = parent[u]) {
        if (fitted[u]) {
          r = std::min(r, fitted_radius[u]);
          break;
        }
      }
      for (std::uint32_t v : chain) {
        if (candidate[v] && r_of[v] == 0) r_of[v] = r;
      }
    }
  }
  std::vector<std::uint8_t> placed(n, 0);
  std::vector<Eigen::Vector3d> placed_pos(n);
  std::vector<double> placed_radius(n, 0.0);
  tbb::parallel_for(std::size_t(0), n, [&](std::size_t vi) {
    const std::uint32_t v = std::uint32_t(vi);
    const double r = r_of[v];
    if (!candidate[v] || !(r >= p.spacing)) return;
    Frame fr;
    if (!gather(v, r, fr)) return;
    Eigen::Vector2d m, normal;
    const int side = bend(m, normal);
    if (side == 0) return;
    const KnownRadiusFit f = fit_circle_known_radius(pts, w, r, m + side * 0.7 * r * normal, noise);
    if (!f.valid || (f.centre - m).dot(normal) * side <= 0) return;
    const double reach = std::max(2.5 * r, 5 * p.spacing);
    const bool good = f.coverage >= min_arc && f.inlier_fraction >= p.min_inliers &&
                      f.residual <= p.max_residual * r + noise && f.centre.norm() + r <= reach &&
                      f.centre.norm() <= p.max_shift * r + 2 * p.spacing;
    if (!good) return;
    placed[v] = 1;
    placed_pos[v] = fr.x + f.centre.x() * fr.e1 + f.centre.y() * fr.e2;
    placed_radius[v] = r;
  });
  std::size_t count = 0;
  for (std::size_t v = 0; v < n; ++v) {
    if (!placed[v]) continue;
    pos[v] = placed_pos[v], fitted[v] = 1, fitted_radius[v] = placed_radius[v];
    ++count;
  }
  return count;
}

}  // namespace ramus::bsg
