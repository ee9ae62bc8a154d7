// Section 4.2 of Livny et al. 2010. Both optimizations are linear least squares over a tree;
// their normal equations are sparse, symmetric positive definite and tree-structured, so a
// sparse LDLT with a fill-reducing ordering factors them in linear time.
#include "reconstruct/bsg/refine.h"

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <cmath>

#include "reconstruct/bsg/kdtree.h"

namespace ramus::bsg {

namespace {

using Triplets = std::vector<Eigen::Triplet<double>>;

// Adds w * |x_a - x_b|^2 to the quadratic form.
void add_difference(Triplets& t, std::uint32_t a, std::uint32_t b, double w) {
  t.emplace_back(a, a, w);
  t.emplace_back(b, b, w);
  t.emplace_back(a, b, -w);
  t.emplace_back(b, a, -w);
}

Eigen::MatrixXd solve(std::size_t n, const Triplets& t, const Eigen::MatrixXd& rhs) {
  Eigen::SparseMatrix<double> m{Eigen::Index(n), Eigen::Index(n)};
  m.setFromTriplets(t.begin(), t.end());
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(m);
  if (ldlt.info() != Eigen::Success) return Eigen::MatrixXd();
  Eigen::MatrixXd x = ldlt.solve(rhs);
  if (ldlt.info() != Eigen::Success || !x.allFinite()) return Eigen::MatrixXd();
  return x;
}

}  // namespace

void importance_weights(Bsg& bsg, double own) {
  const std::size_t n = bsg.size();
  bsg.weight.assign(n, own);
  // Children come after parents, so one reverse sweep accumulates subtree sums.
  for (std::size_t i = n; i-- > 1;) {
    const std::uint32_t p = bsg.parent[i];
    bsg.weight[p] += bsg.weight[i] + (bsg.pos[i] - bsg.pos[p]).norm();
  }
  const double root = n ? bsg.weight[0] : 1.0;
  for (double& c : bsg.weight) c /= root;
}

std::vector<Eigen::Vector3d> orientation_field(const Bsg& bsg) {
  const std::size_t n = bsg.size();
  const auto& c = bsg.weight;
  Triplets t;
  t.reserve(6 * n);
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(Eigen::Index(n), 3);
  Eigen::Vector3d root_dir = Eigen::Vector3d::Zero();
  for (std::uint32_t v = 1; v < n; ++v) {
    const std::uint32_t p = bsg.parent[v];
    // Eq. 1: ((c_vp + c_v) / 2 |o_vp - o_v|)^2.
    const double w1 = 0.25 * (c[p] + c[v]) * (c[p] + c[v]);
    add_difference(t, p, v, w1);
    // Eq. 2: (c_v |o_v - e(v_p, v) / |e(v_p, v)||)^2.
    const Eigen::Vector3d e = bsg.pos[v] - bsg.pos[p];
    const double len = e.norm();
    const Eigen::Vector3d dir = len > 0 ? Eigen::Vector3d(e / len) : Eigen::Vector3d::UnitZ();
    const double w2 = c[v] * c[v];
    t.emplace_back(v, v, w2);
    rhs.row(v) += w2 * dir.transpose();
    if (p == 0) root_dir += c[v] * dir;
  }
  // The root has no incoming edge; Eq. 2 is given the weighted direction of its children so that
  // the system stays definite for a root without children too.
  if (n) {
    root_dir =
        root_dir.norm() > 0 ? Eigen::Vector3d(root_dir.normalized()) : Eigen::Vector3d::UnitZ();
    t.emplace_back(0, 0, c[0] * c[0]);
    rhs.row(0) += c[0] * c[0] * root_dir.transpose();
  }
  Eigen::MatrixXd x = solve(n, t, rhs);
  std::vector<Eigen::Vector3d> o(n);
  for (std::size_t v = 0; v < n; ++v) {
    Eigen::Vector3d ov =
        x.rows() ? Eigen::Vector3d(x.row(Eigen::Index(v)).transpose()) : Eigen::Vector3d::Zero();
    o[v] = ov.norm() > 1e-12 ? Eigen::Vector3d(ov.normalized()) : Eigen::Vector3d::UnitZ();
  }
  return o;
}

std::vector<Eigen::Vector3d> smoothed_positions(const Bsg& bsg,
                                                const std::vector<Eigen::Vector3d>& orient) {
  const std::size_t n = bsg.size();
  if (n < 2) return bsg.pos;
  const auto& c = bsg.weight;
  Triplets t;
  t.reserve(8 * n);
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(Eigen::Index(n), 3);
  for (std::uint32_t u = 1; u < n; ++u) {
    // The edge e(u, v) of Eq. 3 and 4 with u the child and v = parent(u): the orientation field
    // points from parent to child (Eq. 2), so u' - v' should follow it.
    const std::uint32_t v = bsg.parent[u];
    const double len = (bsg.pos[u] - bsg.pos[v]).norm();
    Eigen::Vector3d osum = orient[u] + orient[v];
    osum = osum.norm() > 1e-12 ? Eigen::Vector3d(osum.normalized()) : orient[u];
    const Eigen::Vector3d target = len * osum;
    // Eq. 3: ((c_u + c_v) / 2 |(u' - v') - |u - v| (o_u + o_v) / |o_u + o_v||)^2.
    const double w3 = 0.25 * (c[u] + c[v]) * (c[u] + c[v]);
    add_difference(t, u, v, w3);
    rhs.row(u) += w3 * target.transpose();
    rhs.row(v) -= w3 * target.transpose();
    // Eq. 4: (c_v |(u' + v') / 2 - (u + v) / 2|)^2, i.e. the edge centre stays put.
    const double w4 = c[v] * c[v];
    const Eigen::Vector3d mid = 0.5 * (bsg.pos[u] + bsg.pos[v]);
    for (std::uint32_t a : {u, v}) {
      for (std::uint32_t b : {u, v}) t.emplace_back(a, b, 0.25 * w4);
      rhs.row(a) += 0.5 * w4 * mid.transpose();
    }
  }
  Eigen::MatrixXd x = solve(n, t, rhs);
  if (!x.rows()) return bsg.pos;
  std::vector<Eigen::Vector3d> out(n);
  for (std::size_t i = 0; i < n; ++i) out[i] = x.row(Eigen::Index(i)).transpose();
  return out;
}

void refine(Bsg& bsg, double own) {
  importance_weights(bsg, own);
  if (bsg.size() < 2) return;
  bsg.pos = smoothed_positions(bsg, orientation_field(bsg));
}

Graph reweighted(const Graph& base, const PointIndex& index, const std::vector<Bsg>& refined,
                 double strength, double max_new_edge) {
  Graph g = base;
  for (const Bsg& b : refined) {
    for (std::uint32_t u = 1; u < b.size(); ++u) {
      const std::uint32_t v = b.parent[u];
      const std::uint32_t pu = index.nearest(b.pos[u]);
      const std::uint32_t pv = index.nearest(b.pos[v]);
      if (pu == pv || pu == kNone || pv == kNone) continue;
      const Eigen::Vector3d e = b.pos[u] - b.pos[v];
      const Eigen::Vector3d ep = base.pos[pu] - base.pos[pv];
      if (e.norm() == 0 || ep.norm() == 0) continue;
      const double cosine = std::abs(e.normalized().dot(ep.normalized()));
      const double factor = 1.0 - strength * cosine;
      // The paper's e_P lives in the complete graph on P: a missing short edge is added.
      if (!g.scale_edge(pu, pv, factor) && ep.norm() <= max_new_edge) {
        g.add_edge(pu, pv, ep.squaredNorm() * factor);
      }
    }
  }
  return g;
}

}  // namespace ramus::bsg
