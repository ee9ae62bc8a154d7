#include "reconstruct/bsg/circle_fit.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdint>

#include "core/rng.h"

namespace ramus::bsg {

namespace {

double weight_of(const std::vector<double>& w, std::size_t i) { return w.empty() ? 1.0 : w[i]; }

// The work space of fit_circle, one per thread: the centre lines fit thousands of slabs, and
// allocating a dozen vectors for each fit was a few percent of the reconstruction's time.
struct CircleScratch {
  std::vector<std::size_t> idx;
  std::vector<double> key, near_w, e, len, near_e, inlier_e, ang;
  std::vector<double> x, y, w;  // the points' coordinates and weights (1 when none are given)
  std::vector<Eigen::Vector2d> near;
  std::vector<char> in;
  // consensus: the points near a candidate, and their squared distances
  std::vector<std::uint32_t> sel;
  std::vector<double> sel_d2;
  std::vector<CircleFit> starts;
};
thread_local CircleScratch scratch;

double arc_coverage(const std::vector<Eigen::Vector2d>& pts, const std::vector<char>& use,
                    const Eigen::Vector2d& c) {
  std::vector<double>& ang = scratch.ang;
  ang.clear();
  for (std::size_t i = 0; i < pts.size(); ++i) {
    if (use[i]) ang.push_back(std::atan2(pts[i].y() - c.y(), pts[i].x() - c.x()));
  }
  return angular_coverage(ang);
}

// The circle through three points (invalid when they are nearly collinear).
CircleFit circle_through(const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                         const Eigen::Vector2d& c) {
  CircleFit f;
  const Eigen::Vector2d ab = b - a, ac = c - a;
  const double d = 2 * (ab.x() * ac.y() - ab.y() * ac.x());
  if (!(std::abs(d) > 1e-12 * (ab.squaredNorm() + ac.squaredNorm()))) return f;
  const Eigen::Vector2d u((ac.y() * ab.squaredNorm() - ab.y() * ac.squaredNorm()) / d,
                          (ab.x() * ac.squaredNorm() - ac.x() * ab.squaredNorm()) / d);
  f.centre = a + u;
  f.radius = u.norm();
  f.valid = std::isfinite(f.radius);
  return f;
}

// robust_weight(), both cases of each weight computed so that the choice needs no branch.
inline double robust_weight_of(double u, bool tukey) {
  if (tukey) {
    const double t = u / 4.685;
    const double biweight = (1 - t * t) * (1 - t * t);
    return t < 1 ? biweight : 0.0;
  }
  const double huber = 1.345 / u;
  return u <= 1.345 ? 1.0 : huber;
}

// Consensus of a candidate: the weight of the points within tau of it, each counted with a
// truncated quadratic so that the tighter of two circles wins. `sel` and `d2s` are work space of
// n entries.
double consensus(std::size_t n, const double* x, const double* y, const double* w,
                 const CircleFit& f, double tau, std::uint32_t* sel, double* d2s) {
  // Most points are far from a candidate: they are skipped on their squared distance (bounds
  // widened by a relative 1e-9, so no point within tau is skipped through rounding), and the
  // square root is taken only of the others. The near ones are listed first, in order, without
  // a branch (which points are near is unpredictable, and the mispredicted branch was most of
  // this loop's time), then summed as before.
  const double lo = f.radius > tau ? (f.radius - tau) * (f.radius - tau) * (1 - 1e-9) : 0.0;
  const double hi = (f.radius + tau) * (f.radius + tau) * (1 + 1e-9);
  const double cx = f.centre.x(), cy = f.centre.y(), r = f.radius;
  std::size_t m = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double dx = x[i] - cx, dy = y[i] - cy;
    const double d2 = dx * dx + dy * dy;
    sel[m] = std::uint32_t(i), d2s[m] = d2;
    m += !(d2 < lo) & !(d2 > hi);
  }
  double score = 0;
  for (std::size_t k = 0; k < m; ++k) {
    const double e = (std::sqrt(d2s[k]) - r) / tau;
    if (std::abs(e) < 1) score += w[sel[k]] * (1 - e * e);
  }
  return score;
}

// The k-th smallest of a[0, n) (a is reordered): quickselect with a median-of-three pivot and a
// partition without branches on the data (Lomuto's, swapping unconditionally). The value is the
// k-th order statistic whatever the algorithm, so this returns what std::nth_element returned;
// it is about three times faster on the fits' 10-300 residuals, where nth_element's partition
// mispredicts every other comparison (the fits' robust scales were a tenth of a reconstruction).
double kth_smallest(double* a, std::size_t n, std::size_t k) {
  std::size_t lo = 0, hi = n;
  while (hi - lo > 12) {
    const double x = a[lo], y = a[lo + (hi - lo) / 2], z = a[hi - 1];
    const double pivot = std::max(std::min(x, y), std::min(std::max(x, y), z));
    // [lo, m) < pivot, then (when that was empty: the pivot is the least) [lo, m) == pivot.
    std::size_t m = lo;
    for (std::size_t i = lo; i < hi; ++i) {
      const double v = a[i];
      a[i] = a[m], a[m] = v;
      m += v < pivot;
    }
    if (k < m) {
      hi = m;
      continue;
    }
    if (m == lo) {
      for (std::size_t i = lo; i < hi; ++i) {
        const double v = a[i];
        a[i] = a[m], a[m] = v;
        m += v <= pivot;
      }
      if (m == lo) {  // NaNs: no order to exploit
        std::nth_element(a + lo, a + k, a + hi);
        return a[k];
      }
      if (k < m) return pivot;
    }
    lo = m;
  }
  for (std::size_t i = lo + 1; i < hi; ++i) {
    const double v = a[i];
    std::size_t j = i;
    for (; j > lo && a[j - 1] > v; --j) a[j] = a[j - 1];
    a[j] = v;
  }
  return a[k];
}

// 1.4826 x the median of |e[0..n)| (e's values are lost).
double robust_scale_of(double* e, std::size_t n) {
  // Unweighted: the weights are point counts of near-uniform voxels, and a selection keeps the
  // fits cheap.
  if (n == 0) return 0.0;
  for (std::size_t i = 0; i < n; ++i) e[i] = std::abs(e[i]);
  return 1.4826 * kth_smallest(e, n, n / 2);
}

}  // namespace

double robust_scale(const std::vector<double>& e) {
  std::vector<double> a = e;
  return robust_scale_in_place(a);
}

double robust_scale_in_place(std::vector<double>& e) { return robust_scale_of(e.data(), e.size()); }

double robust_weight(double u, bool tukey) { return robust_weight_of(u, tukey); }

double angular_coverage(std::vector<double>& ang) {
  if (ang.size() < 2) return 0.0;
  std::sort(ang.begin(), ang.end());
  double gap = ang.front() + 2 * M_PI - ang.back();
  for (std::size_t i = 1; i < ang.size(); ++i) gap = std::max(gap, ang[i] - ang[i - 1]);
  return 2 * M_PI - gap;
}

CircleFit taubin_circle(const std::vector<Eigen::Vector2d>& pts,
                        const std::vector<double>& weights) {
  CircleFit f;
  double sw = 0;
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  for (std::size_t i = 0; i < pts.size(); ++i)
    sw += weight_of(weights, i), mean += weight_of(weights, i) * pts[i];
  if (pts.size() < 3 || !(sw > 0)) return f;
  mean /= sw;
  double mxx = 0, myy = 0, mxy = 0, mxz = 0, myz = 0, mzz = 0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const double w = weight_of(weights, i) / sw;
    const double x = pts[i].x() - mean.x(), y = pts[i].y() - mean.y(), z = x * x + y * y;
    mxx += w * x * x, myy += w * y * y, mxy += w * x * y;
    mxz += w * x * z, myz += w * y * z, mzz += w * z * z;
  }
  // Chernov's Newton iteration on Taubin's characteristic polynomial, from x = 0.
  const double mz = mxx + myy, cov_xy = mxx * myy - mxy * mxy, var_z = mzz - mz * mz;
  const double a3 = 4 * mz, a2 = -3 * mz * mz - mzz;
  const double a1 = var_z * mz + 4 * cov_xy * mz - mxz * mxz - myz * myz;
  const double a0 = mxz * (mxz * myy - myz * mxy) + myz * (myz * mxx - mxz * mxy) - var_z * cov_xy;
  double x = 0, y = a0;
  for (int it = 0; it < 99; ++it) {
    const double dy = a1 + x * (2 * a2 + 3 * a3 * x);
    const double xn = x - y / dy;
    if (xn == x || !std::isfinite(xn)) break;
    const double yn = a0 + xn * (a1 + xn * (a2 + xn * a3));
    if (std::abs(yn) >= std::abs(y)) break;
    x = xn, y = yn;
  }
  const double det = x * x - x * mz + cov_xy;
  if (!(std::abs(det) > 0)) return f;
  const Eigen::Vector2d c((mxz * (myy - x) - myz * mxy) / det / 2,
                          (myz * (mxx - x) - mxz * mxy) / det / 2);
  f.centre = c + mean;
  f.radius = std::sqrt(c.squaredNorm() + mz);
  f.valid = std::isfinite(f.radius) && std::isfinite(f.centre.x()) && std::isfinite(f.centre.y());
  return f;
}

CircleFit fit_circle(const std::vector<Eigen::Vector2d>& pts, const std::vector<double>& weights,
                     double noise, int iterations) {
  // Starts: Taubin's circle through all points, through the half nearest the slab's origin (the
  // node, which lies on or in the branch it stands for), and through random triples (RANSAC,
  // Fischler & Bolles 1981): a slab that also cuts a second branch has more than one circle,
  // and an algebraic fit to both lies between them. The start most points agree with wins.
  const std::size_t n = pts.size();
  CircleFit f = taubin_circle(pts, weights);
  if (n < 3) return f;
  const double tau = 2.5 * std::max(noise, 1e-12);
  std::vector<CircleFit>& starts = scratch.starts;
  starts.assign(1, f);
  {
    // The keys are computed once (the sort compares each point's about 2 log n times).
    std::vector<std::size_t>& idx = scratch.idx;
    std::vector<double>& key = scratch.key;
    idx.resize(n), key.resize(n);
    for (std::size_t i = 0; i < n; ++i) idx[i] = i, key[i] = pts[i].squaredNorm();
    std::sort(idx.begin(), idx.end(),
              [&](std::size_t a, std::size_t b) { return key[a] < key[b]; });
    std::vector<Eigen::Vector2d>& near = scratch.near;
    std::vector<double>& near_w = scratch.near_w;
    near.clear(), near_w.clear();
    for (std::size_t k = 0; k < std::max<std::size_t>(3, n / 2); ++k) {
      near.push_back(pts[idx[k]]);
      if (!weights.empty()) near_w.push_back(weights[idx[k]]);
    }
    starts.push_back(taubin_circle(near, near_w));
  }
  Rng rng(0x51ab + n);
  for (int k = 0; k < 16; ++k) {
    const std::size_t a = rng.below(n), b = rng.below(n), c = rng.below(n);
    if (a == b || b == c || a == c) continue;
    starts.push_back(circle_through(pts[a], pts[b], pts[c]));
  }
  std::vector<double>&x = scratch.x, &y = scratch.y, &w = scratch.w;
  x.resize(n), y.resize(n), w.resize(n), scratch.sel.resize(n), scratch.sel_d2.resize(n);
  for (std::size_t i = 0; i < n; ++i)
    x[i] = pts[i].x(), y[i] = pts[i].y(), w[i] = weight_of(weights, i);
  double best = -1;
  for (const CircleFit& s : starts) {
    if (!s.valid) continue;
    const double score = consensus(n, x.data(), y.data(), w.data(), s, tau, scratch.sel.data(),
                                   scratch.sel_d2.data());
    if (score > best) best = score, f = s;
  }
  if (!f.valid) return f;
  // The loops below read the points as separate coordinate arrays and accumulate in scalars:
  // the same operations in the same order as the Eigen expressions they replace (so the same
  // bits), but an Eigen outer product accumulated per point went through the stack, and its
  // stores and wider loads stalled the loop (half of this function's time).
  std::vector<double>&e = scratch.e, &len = scratch.len, &near_e = scratch.near_e;
  e.resize(n), len.resize(n), near_e.resize(n);
  const double* px = scratch.x.data();
  const double* py = scratch.y.data();
  const double* pw = scratch.w.data();
  double* pe = e.data();
  double* plen = len.data();
  double cx = f.centre.x(), cy = f.centre.y();
  double r = f.radius, scale = 0;
  // The scale comes from the points near the current circle (within 4 tau), so the points of
  // another branch do not inflate it and turn themselves into inliers.
  auto residuals = [&] {
    double* ne = near_e.data();
    std::size_t m = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const double dx = px[i] - cx, dy = py[i] - cy;
      plen[i] = std::sqrt(dx * dx + dy * dy);  // kept for the Jacobian
      pe[i] = plen[i] - r;
      ne[m] = pe[i];  // kept when near, without a branch
      m += std::abs(pe[i]) < 4 * tau;
    }
    scale = std::max(m == 0 ? tau : robust_scale_of(ne, m), noise);
  };
  residuals();
  for (int it = 0; it < iterations; ++it) {
    // Huber for the first third (a convex start), Tukey's biweight after (outliers get weight 0).
    const bool tukey = it >= iterations / 3;
    // J^T W J and J^T W e of the rows j = (-dx / len, -dy / len, -1), entry (a, b) of the outer
    // product being j_b (w j_a) as Eigen's `w * j * j.transpose()` computes it.
    // The points that count (positive weight, off the centre) are listed first without a branch,
    // as in consensus().
    std::uint32_t* sel = scratch.sel.data();
    double* sel_w = scratch.sel_d2.data();
    std::size_t m = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const double rw = robust_weight_of(std::abs(pe[i]) / scale, tukey) * pw[i];
      sel[m] = std::uint32_t(i), sel_w[m] = rw;
      m += !(rw <= 0) & (plen[i] > 0);
    }
    double a00 = 0, a01 = 0, a02 = 0, a10 = 0, a11 = 0, a12 = 0, a20 = 0, a21 = 0, a22 = 0;
    double g0 = 0, g1 = 0, g2 = 0;
    for (std::size_t k = 0; k < m; ++k) {
      const std::size_t i = sel[k];
      const double rw = sel_w[k];
      const double jx = -(px[i] - cx) / plen[i], jy = -(py[i] - cy) / plen[i];
      const double wx = rw * jx, wy = rw * jy, wz = -rw;
      a00 += jx * wx, a01 += jy * wx, a02 -= wx;
      a10 += jx * wy, a11 += jy * wy, a12 -= wy;
      a20 += jx * wz, a21 += jy * wz, a22 -= wz;
      g0 += wx * pe[i], g1 += wy * pe[i], g2 += wz * pe[i];
    }
    Eigen::Matrix3d jtj;
    jtj << a00, a01, a02, a10, a11, a12, a20, a21, a22;
    const Eigen::Vector3d jte(g0, g1, g2);
    jtj.diagonal() *= 1.0 + 1e-9;
    const Eigen::Vector3d step = jtj.ldlt().solve(-jte);
    if (!step.allFinite()) break;
    cx += step.x(), cy += step.y();
    r += step.z();
    residuals();
    if (step.norm() < 1e-6 * std::max(r, 1e-9)) break;
  }
  const Eigen::Vector2d c(cx, cy);
  // Inliers: within 2.5 robust scales of the circle (Tukey's weight is tiny beyond that).
  std::vector<char>& in = scratch.in;
  in.assign(n, 0);
  std::vector<double>& inlier_e = scratch.inlier_e;
  inlier_e.clear();
  double win = 0, wall = 0;
  for (std::size_t i = 0; i < n; ++i) {
    wall += weight_of(weights, i);
    if (std::abs(e[i]) <= 2.5 * scale) {
      in[i] = 1;
      win += weight_of(weights, i);
      inlier_e.push_back(e[i]);
    }
  }
  f.centre = c;
  f.radius = std::abs(r);
  f.residual = inlier_e.empty() ? scale : robust_scale_in_place(inlier_e);
  f.coverage = arc_coverage(pts, in, c);
  f.inlier_fraction = wall > 0 ? win / wall : 0;
  f.valid = std::isfinite(f.radius) && c.allFinite() && f.radius > 0;
  return f;
}

namespace {

// The work space of split_two_arcs (fit_circle has its own, which the sides' fits use).
struct SplitScratch {
  std::vector<std::uint32_t> order;
  std::vector<double> angle, distance, side_w;
  std::vector<Eigen::Vector2d> side;
};
thread_local SplitScratch split_scratch;

// The median distance of the points order[a, b) to the circle (c, r).
double median_distance(const std::vector<Eigen::Vector2d>& pts, std::size_t a, std::size_t b,
                       const Eigen::Vector2d& c, double r) {
  std::vector<double>& d = split_scratch.distance;
  d.clear();
  for (std::size_t k = a; k < b; ++k) {
    d.push_back(std::abs((pts[split_scratch.order[k]] - c).norm() - r));
  }
  return kth_smallest(d.data(), d.size(), d.size() / 2);
}

// The points order[a, b) and their weights, for a side's fit.
void gather_side(const std::vector<Eigen::Vector2d>& pts, const std::vector<double>& weights,
                 std::size_t a, std::size_t b) {
  SplitScratch& s = split_scratch;
  s.side.clear(), s.side_w.clear();
  for (std::size_t k = a; k < b; ++k) {
    s.side.push_back(pts[s.order[k]]), s.side_w.push_back(weight_of(weights, s.order[k]));
  }
}

}  // namespace

bool split_two_arcs(const std::vector<Eigen::Vector2d>& pts, const std::vector<double>& weights,
                    const CircleFit& whole, double noise, CircleFit& first, CircleFit& second) {
  // Each side needs 8 points, as a slab does (centre_line.cpp, fit_slab).
  constexpr std::size_t kMinSide = 8;
  constexpr int kSplits = 16;
  const std::size_t m = pts.size();
  if (!whole.valid || m < 2 * kMinSide) return false;
  SplitScratch& s = split_scratch;
  s.order.resize(m), s.angle.resize(m);
  for (std::size_t i = 0; i < m; ++i) {
    s.order[i] = std::uint32_t(i);
    s.angle[i] = std::atan2(pts[i].y() - whole.centre.y(), pts[i].x() - whole.centre.x());
  }
  std::sort(s.order.begin(), s.order.end(), [&](std::uint32_t a, std::uint32_t b) {
    return s.angle[a] < s.angle[b] || (s.angle[a] == s.angle[b] && a < b);
  });
  // The order starts after the widest angular gap, so that neither arc is cut in two by the
  // wrap-around at -pi.
  std::size_t start = 0;
  double widest = s.angle[s.order[0]] + 2 * M_PI - s.angle[s.order[m - 1]];
  for (std::size_t k = 1; k < m; ++k) {
    const double gap = s.angle[s.order[k]] - s.angle[s.order[k - 1]];
    if (gap > widest) widest = gap, start = k;
  }
  std::rotate(s.order.begin(), s.order.begin() + std::ptrdiff_t(start), s.order.end());
  const double one = median_distance(pts, 0, m, whole.centre, whole.radius);
  if (!(one > 2 * noise)) return false;
  double best_cost = 0;
  std::size_t best_k = 0;
  for (int i = 1; i < kSplits; ++i) {
    const std::size_t k = m * std::size_t(i) / kSplits;
    if (k < kMinSide || m - k < kMinSide) continue;
    gather_side(pts, weights, 0, k);
    const CircleFit a = taubin_circle(s.side, s.side_w);
    gather_side(pts, weights, k, m);
    const CircleFit b = taubin_circle(s.side, s.side_w);
    if (!a.valid || !b.valid) continue;
    const double cost = (median_distance(pts, 0, k, a.centre, a.radius) * double(k) +
                         median_distance(pts, k, m, b.centre, b.radius) * double(m - k)) /
                        double(m);
    if (best_k == 0 || cost < best_cost) best_cost = cost, best_k = k;
  }
  if (best_k == 0 || !(best_cost < 0.5 * one)) return false;
  gather_side(pts, weights, 0, best_k);
  first = fit_circle(s.side, s.side_w, noise);
  gather_side(pts, weights, best_k, m);
  second = fit_circle(s.side, s.side_w, noise);
  return true;
}

}  // namespace ramus::bsg
