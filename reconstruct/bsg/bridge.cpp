#include "reconstruct/bsg/bridge.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "reconstruct/bsg/graph.h"
#include "reconstruct/bsg/kdtree.h"

namespace ramus::bsg {

namespace {

struct Gap {
  double d2 = std::numeric_limits<double>::infinity();
  std::uint32_t from = kNone, to = kNone;
};

// A component not reached from a root. When elongated, it is a piece of one branch whose
// continuation the scan lost: its axis, the vertices at both ends along it, and the nearest
// reached vertex found so far in the cone ahead of each end.
struct Fragment {
  bool elongated = false;
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();
  std::array<std::uint32_t, 2> end{kNone, kNone};
  std::array<Gap, 2> ahead;
  std::array<Gap, 2> ahead_far;  // the same within the hidden-limb reach, when it has one
};

std::vector<Fragment> fragments(const Graph& g, const std::vector<std::uint32_t>& label,
                                std::uint32_t ncomp, const std::vector<std::uint8_t>& attached,
                                const BridgeParams& p) {
  std::vector<Fragment> f(ncomp);
  std::vector<double> w(ncomp, 0.0);
  std::vector<std::size_t> n(ncomp, 0);
  std::vector<Eigen::Vector3d> origin(ncomp), sum(ncomp, Eigen::Vector3d::Zero());
  std::vector<Eigen::Matrix3d> sq(ncomp, Eigen::Matrix3d::Zero());
  for (std::uint32_t v = 0; v < g.size(); ++v) {
    const std::uint32_t c = label[v];
    if (attached[c]) continue;
    if (n[c] == 0) origin[c] = g.pos[v];  // moments about a vertex of the fragment: no cancellation
    const Eigen::Vector3d d = g.pos[v] - origin[c];
    const double wv = double(g.points[v]);
    w[c] += wv, ++n[c], sum[c] += wv * d, sq[c] += wv * d * d.transpose();
  }
  std::vector<std::array<double, 2>> extent(
      ncomp, {std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()});
  for (std::uint32_t c = 0; c < ncomp; ++c) {
    if (attached[c] || n[c] < p.min_vertices || !(w[c] > 0)) continue;
    const Eigen::Vector3d mean = sum[c] / w[c];
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig;
    eig.computeDirect(sq[c] / w[c] - mean * mean.transpose());
    const Eigen::Vector3d lambda = eig.eigenvalues();  // ascending
    if (!(lambda(2) > 0) || lambda(2) < p.linearity * lambda(1)) continue;
    f[c].elongated = true;
    f[c].axis = eig.eigenvectors().col(2).normalized();
  }
  for (std::uint32_t v = 0; v < g.size(); ++v) {
    const std::uint32_t c = label[v];
    if (attached[c] || !f[c].elongated) continue;
    const double t = (g.pos[v] - origin[c]).dot(f[c].axis);
    if (t < extent[c][0]) extent[c][0] = t, f[c].end[0] = v;
    if (t > extent[c][1]) extent[c][1] = t, f[c].end[1] = v;
  }
  return f;
}

// The indexed vertex nearest to `from` within the cone of half-angle asin(sin_cone) around
// `dir`, at most max_gap away. Balls inside the cone, centred on its axis at growing distances
// (each 1.6 times the last, so consecutive balls overlap), are searched nearest first; the
// search stops one ball after the first hit.
Gap nearest_ahead(const PointIndex& index, const Graph& g, std::uint32_t from,
                  const Eigen::Vector3d& dir, double max_gap, double sin_cone) {
  Gap best;
  std::array<std::uint32_t, 16> ids;
  std::array<double, 16> d2;
  int after_hit = 0;
  for (double t = max_gap / 64; t <= 1.6 * max_gap && after_hit < 2; t *= 1.6) {
    const std::size_t m =
        index.knn_within(g.pos[from] + t * dir, ids.size(), t * sin_cone, ids.data(), d2.data());
    for (std::size_t i = 0; i < m; ++i) {
      const double l2 = (g.pos[ids[i]] - g.pos[from]).squaredNorm();
      if (l2 <= max_gap * max_gap && l2 < best.d2) best = {l2, from, ids[i]};
    }
    if (best.to != kNone) ++after_hit;
  }
  return best;
}

}  // namespace

std::size_t bridge_gaps(Graph& graph, const std::vector<std::uint32_t>& roots, double max_gap) {
  BridgeParams p;
  p.max_gap = max_gap;
  return bridge_gaps(graph, roots, p);
}

std::size_t bridge_gaps(Graph& graph, const std::vector<std::uint32_t>& roots,
                        const BridgeParams& params) {
  const double max_gap = params.max_gap;
  std::uint32_t ncomp = 0;
  std::vector<std::uint32_t> label = components(graph, &ncomp);
  std::vector<std::uint8_t> attached(ncomp, 0);
  for (std::uint32_t r : roots) attached[label[r]] = 1;
  std::vector<Fragment> frag = fragments(graph, label, ncomp, attached, params);
  // Each component's reach (squared): max_gap, or hidden_limb_gap when it is long enough.
  std::vector<double> reach2(ncomp, max_gap * max_gap);
  bool any_hidden = false, hidden_phase = false;
  if (params.hidden_limb_gap > max_gap && params.hidden_limb_length > 0) {
    std::vector<Eigen::AlignedBox3d> box(ncomp);
    for (std::uint32_t v = 0; v < graph.size(); ++v) box[label[v]].extend(graph.pos[v]);
    for (std::uint32_t c = 0; c < ncomp; ++c) {
      if (attached[c] || box[c].diagonal().norm() < params.hidden_limb_length) continue;
      reach2[c] = params.hidden_limb_gap * params.hidden_limb_gap;
      any_hidden = true;
    }
  }
  const double cone = params.cone_degrees * M_PI / 180;
  const double cos_cone = std::cos(cone), sin_cone = std::sin(cone);
  const double penalty2 = params.off_axis_penalty * params.off_axis_penalty;
  // The attached set only grows, so each vertex keeps its nearest attached vertex found so far
  // (and each fragment end its nearest one ahead) and each round searches only the vertices
  // attached since the round before: one k-d tree per newly attached batch instead of one over
  // everything attached in every round. A strictly nearer vertex replaces the one kept, so the
  // earliest attached wins a tie.
  std::vector<Gap> nearest(graph.size());
  std::vector<std::uint32_t> fresh;
  for (std::uint32_t v = 0; v < graph.size(); ++v) {
    if (attached[label[v]]) fresh.push_back(v);
  }
  std::size_t bridges = 0;
  // Each round attaches the components whose ranked gap is within twice the smallest, so a
  // chain of fragments is followed link by link rather than jumped across, and a fragment whose
  // only links are off its axis waits until its own branch may have been reached.
  for (int round = 0; round < 10000; ++round) {
    if (std::all_of(attached.begin(), attached.end(), [](auto a) { return a != 0; })) break;
    if (!fresh.empty()) {
      const PointIndex index(graph.pos, std::move(fresh));
      fresh.clear();
      tbb::parallel_for(tbb::blocked_range<std::uint32_t>(0, std::uint32_t(graph.size()), 1024),
                        [&](const tbb::blocked_range<std::uint32_t>& r) {
                          for (std::uint32_t v = r.begin(); v != r.end(); ++v) {
                            if (attached[label[v]]) continue;
                            double d2;
                            const std::uint32_t to = index.nearest(graph.pos[v], &d2);
                            if (to != kNone && d2 < nearest[v].d2) nearest[v] = {d2, v, to};
                          }
                        });
      tbb::parallel_for(std::uint32_t(0), ncomp, [&](std::uint32_t c) {
        if (attached[c] || !frag[c].elongated) return;
        for (int k = 0; k < 2; ++k) {
          const std::uint32_t e = frag[c].end[k];
          const Eigen::Vector3d out = k == 0 ? Eigen::Vector3d(-frag[c].axis) : frag[c].axis;
          const Gap g = nearest_ahead(index, graph, e, out, max_gap, sin_cone);
          if (g.d2 < frag[c].ahead[k].d2) frag[c].ahead[k] = g;
          if (reach2[c] > max_gap * max_gap) {
            const Gap f = nearest_ahead(index, graph, e, out, std::sqrt(reach2[c]), sin_cone);
            if (f.d2 < frag[c].ahead_far[k].d2) frag[c].ahead_far[k] = f;
          }
        }
      });
    }
    // For every component not yet attached, its best link and that link's rank (squared).
    std::vector<Gap> gaps(ncomp);
    for (std::uint32_t v = 0; v < graph.size(); ++v) {
      if (attached[label[v]]) continue;
      Gap& b = gaps[label[v]];
      if (nearest[v].to != kNone && nearest[v].d2 < b.d2) b = nearest[v];
    }
    std::vector<double> rank(ncomp, std::numeric_limits<double>::infinity());
    for (std::uint32_t c = 0; c < ncomp; ++c) {
      if (attached[c]) continue;
      // Hidden limbs reach farther only once nothing else can be bridged.
      const bool far = hidden_phase && reach2[c] > max_gap * max_gap;
      const Gap closest = gaps[c];
      gaps[c] = {};
      if (closest.to != kNone && closest.d2 <= (far ? reach2[c] : max_gap * max_gap)) {
        gaps[c] = closest;
        rank[c] = closest.d2;
      }
      if (!frag[c].elongated) continue;
      if (gaps[c].to != kNone) {
        const Eigen::Vector3d link = graph.pos[gaps[c].to] - graph.pos[gaps[c].from];
        if (std::abs(link.dot(frag[c].axis)) < cos_cone * link.norm()) rank[c] *= penalty2;
      }
      for (const Gap& a : far ? frag[c].ahead_far : frag[c].ahead) {
        if (a.to != kNone && a.d2 < rank[c]) gaps[c] = a, rank[c] = a.d2;
      }
    }
    double smallest = std::numeric_limits<double>::infinity();
    for (std::uint32_t c = 0; c < ncomp; ++c) {
      if (!attached[c]) smallest = std::min(smallest, rank[c]);
    }
    if (!std::isfinite(smallest)) {
      if (hidden_phase || !any_hidden) break;
      hidden_phase = true;
      continue;
    }
    const double limit = 4 * smallest;
    std::vector<std::uint8_t> now(ncomp, 0);
    for (std::uint32_t c = 0; c < ncomp; ++c) {
      if (attached[c] || rank[c] > limit) continue;
      graph.add_edge(gaps[c].from, gaps[c].to, gaps[c].d2);
      attached[c] = 1;
      now[c] = 1;
      ++bridges;
    }
    for (std::uint32_t v = 0; v < graph.size(); ++v) {
      if (now[label[v]]) fresh.push_back(v);
    }
  }
  return bridges;
}

}  // namespace ramus::bsg
