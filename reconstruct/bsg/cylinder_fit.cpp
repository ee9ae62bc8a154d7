#include "reconstruct/bsg/cylinder_fit.h"

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

#include "reconstruct/bsg/bsg.h"
#include "reconstruct/bsg/circle_fit.h"

namespace ramus::bsg {

namespace {

double weight_of(const std::vector<double>& w, std::size_t i) { return w.empty() ? 1.0 : w[i]; }

// One fit from one start direction; `score` gets its consensus (as in circle_fit.cpp: each
// point within 2.5 noise of the surface counts with a truncated quadratic).
CylinderFit fit_from(const std::vector<Eigen::Vector3d>& pts, const std::vector<double>& weights,
                     const Eigen::Vector3d& start, const Eigen::Vector3d& direction, double span,
                     double noise, int iterations, double& score) {
  CylinderFit out;
  score = -1;
  const std::size_t n = pts.size();
  if (n < 8 || !(direction.norm() > 0)) return out;
  Eigen::Vector3d d = direction.normalized(), e1, e2;
  perpendicular_frame(d, e1, e2);
  // 1. The circle of the points seen along the start direction.
  // Per-thread work space (chain_cylinders.h fits hundreds of pieces, twice each).
  thread_local std::vector<Eigen::Vector2d> uv;
  thread_local std::vector<double> e, t, near_e, ang, inlier_e, sel_w;
  thread_local std::vector<std::uint32_t> sel;
  thread_local std::vector<Eigen::Vector3d> nrm;
  uv.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector3d q = pts[i] - start;
    uv[i] = {q.dot(e1), q.dot(e2)};
  }
  const CircleFit c0 = fit_circle(uv, weights, noise);
  if (!c0.valid) return out;
  Eigen::Vector3d q = start + c0.centre.x() * e1 + c0.centre.y() * e2;
  double r = c0.radius;
  // 2. Gauss-Newton over (direction tilt a, b; axis shift u, v; radius), re-linearised around
  // the current axis each step.
  e.resize(n), t.resize(n), nrm.resize(n);
  const double tau = 2.5 * std::max(noise, 1e-12);
  double scale = 0;
  auto residuals = [&] {
    near_e.resize(n);
    std::size_t m = 0;
    const double near = std::max(4 * tau, 0.5 * r);
    for (std::size_t i = 0; i < n; ++i) {
      const Eigen::Vector3d w = pts[i] - q;
      t[i] = w.dot(d);
      const Eigen::Vector3d perp = w - t[i] * d;
      const double rho = perp.norm();
      nrm[i] = rho > 0 ? Eigen::Vector3d(perp / rho) : e1;
      e[i] = rho - r;
      near_e[m] = e[i];  // kept when near, without a branch (which are near is unpredictable)
      m += std::abs(e[i]) < near;
    }
    near_e.resize(m);
    scale = std::max(near_e.empty() ? tau : robust_scale_in_place(near_e), noise);
  };
  residuals();
  for (int it = 0; it < iterations; ++it) {
    const bool tukey = it >= iterations / 3;
    // J^T W J (its lower triangle, the part LDLT reads) and J^T W e in scalars: entry (a, b) is
    // j_b (w j_a), as Eigen's `w * j * j.transpose()` computes it, but an Eigen 5 x 5 outer
    // product accumulated per point went through the stack and stalled the loop.
    std::array<double, 15> lower{};  // row-major: (0,0) (1,0) (1,1) (2,0) ...
    std::array<double, 5> g{};
    // The points with a positive weight are listed first without a branch (which are is
    // unpredictable), then accumulated in order.
    sel.resize(n), sel_w.resize(n);
    std::size_t m = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const double rw = robust_weight(std::abs(e[i]) / scale, tukey) * weight_of(weights, i);
      sel[m] = std::uint32_t(i), sel_w[m] = rw;
      m += !(rw <= 0);
    }
    for (std::size_t k = 0; k < m; ++k) {
      const std::size_t i = sel[k];
      const double rw = sel_w[k];
      const double n1 = nrm[i].dot(e1), n2 = nrm[i].dot(e2);
      const double j[5] = {-t[i] * n1, -t[i] * n2, -n1, -n2, -1.0};
      double w[5];
      for (int a = 0; a < 5; ++a) w[a] = rw * j[a];
      for (int a = 0, k = 0; a < 5; ++a) {
        for (int b = 0; b <= a; ++b, ++k) lower[k] += j[b] * w[a];
        g[a] += w[a] * e[i];
      }
    }
    Eigen::Matrix<double, 5, 5> jtj;
    Eigen::Matrix<double, 5, 1> jte;
    for (int a = 0, k = 0; a < 5; ++a) {
      for (int b = 0; b <= a; ++b, ++k) jtj(a, b) = jtj(b, a) = lower[k];
      jte(a) = g[a];
    }
    jtj.diagonal() *= 1.0 + 1e-6;
    const Eigen::Matrix<double, 5, 1> step = jtj.ldlt().solve(-jte);
    if (!step.allFinite()) break;
    d = (d + step(0) * e1 + step(1) * e2).normalized();
    q += step(2) * e1 + step(3) * e2;
    r += step(4);
    // Keep q level with the gathering point and the frame perpendicular to d.
    q += (start - q).dot(d) * d;
    perpendicular_frame(d, e1, e2);
    residuals();
    if (step.norm() < 1e-6 * std::max(std::abs(r), 1e-9)) break;
  }
  if (!(r > 0) || !q.allFinite() || !d.allFinite()) return out;
  ang.clear(), inlier_e.clear();
  double win = 0, wall = 0;
  std::array<bool, 8> bins{};
  for (std::size_t i = 0; i < n; ++i) {
    wall += weight_of(weights, i);
    if (std::abs(e[i]) > 2.5 * scale) continue;
    win += weight_of(weights, i);
    inlier_e.push_back(e[i]);
    ang.push_back(std::atan2(nrm[i].dot(e2), nrm[i].dot(e1)));
    const double s = (pts[i] - start).dot(d);
    if (span > 0 && std::abs(s) < span)
      bins[std::size_t(std::clamp((s + span) / (2 * span) * 8, 0.0, 7.0))] = true;
  }
  out.point = q;
  out.direction = d;
  out.radius = r;
  out.residual = inlier_e.empty() ? scale : robust_scale_in_place(inlier_e);
  out.coverage = angular_coverage(ang);
  out.inlier_fraction = wall > 0 ? win / wall : 0;
  out.axial_fill = double(std::count(bins.begin(), bins.end(), true)) / 8.0;
  out.valid = true;
  score = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double u = e[i] / tau;
    if (std::abs(u) < 1) score += weight_of(weights, i) * (1 - u * u);
  }
  return out;
}

}  // namespace

CylinderFit fit_cylinder(const std::vector<Eigen::Vector3d>& pts,
                         const std::vector<double>& weights, const Eigen::Vector3d& start,
                         const Eigen::Vector3d& direction, double span, double noise,
                         int iterations) {
  if (pts.size() < 8 || !(direction.norm() > 0)) return {};
  const Eigen::Vector3d d0 = direction.normalized();
  double best_score = -1;
  CylinderFit best = fit_from(pts, weights, start, d0, span, noise, iterations, best_score);
  // A second start along the points' principal axis, when it is within 45 degrees of the given
  // one: a chain that zig-zags over the bark gives a direction that is off by tens of degrees,
  // and the circle seen along it is smeared beyond recognition.
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  double sw = 0;
  for (std::size_t i = 0; i < pts.size(); ++i)
    sw += weight_of(weights, i), mean += weight_of(weights, i) * pts[i];
  mean /= sw;
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const Eigen::Vector3d q = pts[i] - mean;
    cov += weight_of(weights, i) * q * q.transpose();
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
  const Eigen::Vector3d principal = eig.eigenvectors().col(2);
  if (std::abs(principal.dot(d0)) >= std::cos(M_PI / 4) && std::abs(principal.dot(d0)) < 0.999) {
    double score = -1;
    const CylinderFit other =
        fit_from(pts, weights, start, principal.dot(d0) > 0 ? principal : -principal, span, noise,
                 iterations, score);
    if (other.valid && (!best.valid || score > best_score)) best = other;
  }
  return best;
}

}  // namespace ramus::bsg
