#include "reconstruct/bsg/fork_placement.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ramus::bsg {

namespace {

// cos 60 degrees: a chain turning by more than this at c was entered from the side.
constexpr double kTurn = 0.5;
// cos 10 degrees: a branch whose axis is closer to its stem's than this is not placed.
constexpr double kAlong = 0.985;

// Closest approach of the ray o - s d (s >= 0, d unit) to the segment a-b: the distance, the
// ray parameter s and the point on the segment.
struct Approach {
  double dist = std::numeric_limits<double>::infinity(), s = 0, t = 0;
};

Approach ray_segment(const Eigen::Vector3d& o, const Eigen::Vector3d& d, const Eigen::Vector3d& a,
                     const Eigen::Vector3d& b) {
  // Minimise |o - s d - (a + t (b - a))| over s >= 0, t in [0, 1]: sample t finely enough for
  // the few edges tested (a closed form with both clamps is longer than it is worth here).
  Approach best;
  const Eigen::Vector3d ab = b - a;
  for (int k = 0; k <= 32; ++k) {
    const double t = k / 32.0;
    const Eigen::Vector3d p = a + t * ab;
    const double s = std::max(0.0, (o - p).dot(d));
    const double dist = (o - s * d - p).norm();
    if (dist < best.dist) best = {dist, s, t};
  }
  return best;
}

// Parent-first order again after re-attachments (a depth-first walk from the root).
void reorder(Bsg& b, std::vector<std::uint8_t>& fitted) {
  std::vector<std::uint32_t> old_of;
  b = depth_first(b, children_of(b.parent), &old_of);
  std::vector<std::uint8_t> fit(old_of.size());
  for (std::size_t i = 0; i < old_of.size(); ++i) fit[i] = fitted[old_of[i]];
  fitted = std::move(fit);
}

}  // namespace

std::size_t place_forks(Bsg& b, std::vector<std::uint8_t>& fitted, double spacing) {
  const std::size_t n0 = b.size();
  if (n0 < 3 || fitted.size() != n0) return 0;
  auto ch = children_of(b.parent);
  // The child that continues the stem: the thickest (the radii are fitted on the stems this
  // step moves), of equal ones the one with the longest subtree.
  std::vector<double> reach(n0, 0.0);
  for (std::size_t v = n0; v-- > 1;) {
    reach[b.parent[v]] += reach[v] + (b.pos[v] - b.pos[b.parent[v]]).norm();
  }
  auto heaviest = [&](std::uint32_t v, std::uint32_t skip) {
    std::uint32_t best = kNone;
    for (std::uint32_t c : ch[v]) {
      if (c == skip) continue;
      if (best == kNone || b.radius[c] > 1.1 * b.radius[best] ||
          (b.radius[c] >= b.radius[best] / 1.1 && reach[c] > reach[best])) {
        best = c;
      }
    }
    return best;
  };
  std::size_t moved = 0;
  std::vector<std::uint32_t> emptied;  // forks that lost a branch
  for (std::uint32_t f = 0; f < n0; ++f) {
    if (ch[f].empty()) continue;
    const std::uint32_t main = heaviest(f, kNone);
    for (std::uint32_t c : std::vector<std::uint32_t>(ch[f])) {
      // (A split of the stem's first edge may have given c a new parent already.)
      if (!fitted[c] || b.parent[c] != f) continue;
      const bool side = c != main;
      // The branch's axis: from c to the farthest fitted node of its first few along its
      // heaviest chain, at least a radius (and two spacings) away.
      const double rc = std::max(b.radius[c], spacing);
      std::uint32_t far = kNone;
      for (std::uint32_t v = heaviest(c, kNone), k = 0; v != kNone && fitted[v] && k < 4;
           v = heaviest(v, kNone), ++k) {
        far = v;
        if ((b.pos[v] - b.pos[c]).norm() >= 3 * rc) break;
      }
      if (far == kNone || (b.pos[far] - b.pos[c]).norm() < std::max(rc, 2 * spacing)) continue;
      const Eigen::Vector3d d = (b.pos[far] - b.pos[c]).normalized();
      // A continuing chain is only re-attached where it turns back on itself: the BSG entered
      // the branch from a neighbour's bark part-way along it.
      if (!side && (b.pos[c] - b.pos[f]).dot(d) > kTurn * (b.pos[c] - b.pos[f]).norm()) continue;
      // The stem around the fork: edges (parent, child) with both ends fitted, down through
      // the ancestors and up the heaviest chain, within a few stem radii of the fork.
      const double rf = std::max(b.radius[f], spacing);
      const double span = 4 * rf + (b.pos[c] - b.pos[f]).norm();
      std::vector<std::uint32_t> stem;  // child ends of the stem's edges
      double len = 0;
      for (std::uint32_t v = f; b.parent[v] != kNone && len < span; v = b.parent[v]) {
        stem.push_back(v);
        len += (b.pos[v] - b.pos[b.parent[v]]).norm();
      }
      len = 0;
      for (std::uint32_t v = side ? heaviest(f, c) : kNone; v != kNone && len < span;
           v = heaviest(v, kNone)) {
        stem.push_back(v);
        len += (b.pos[v] - b.pos[b.parent[v]]).norm();
      }
      Approach best;
      std::uint32_t edge = kNone;
      for (std::uint32_t q : stem) {
        const std::uint32_t p = b.parent[q];
        if (!fitted[p] || !fitted[q]) continue;
        // A branch leaves its stem at an angle; along the stem the closest approach is
        // anywhere (the stem's own continuation, or a spur chain on its bark).
        const Eigen::Vector3d e = b.pos[q] - b.pos[p];
        if (std::abs(e.dot(d)) > kAlong * e.norm()) continue;
        const Approach a = ray_segment(b.pos[c], d, b.pos[p], b.pos[q]);
        const double rs = std::max(b.radius[p] + a.t * (b.radius[q] - b.radius[p]), spacing);
        if (a.dist <= 0.5 * rs && a.dist < best.dist) best = a, edge = q;
      }
      if (edge == kNone) continue;
      const std::uint32_t p = b.parent[edge];
      const Eigen::Vector3d x = b.pos[p] + best.t * (b.pos[edge] - b.pos[p]);
      if ((x - b.pos[f]).norm() <= std::max(0.25 * rf, 2 * spacing)) continue;
      // The new parent: a node of the stem within two spacings, else a new node on the edge.
      std::uint32_t to;
      if ((x - b.pos[p]).norm() <= 2 * spacing) {
        to = p;
      } else if ((x - b.pos[edge]).norm() <= 2 * spacing) {
        to = edge;
      } else {
        to = std::uint32_t(b.size());
        b.pos.push_back(x);
        b.parent.push_back(p);
        b.vertex.push_back(kNone);
        b.weight.push_back(b.weight[edge]);
        b.radius.push_back(b.radius[p] + best.t * (b.radius[edge] - b.radius[p]));
        b.mass.push_back(0.0);
        fitted.push_back(1);
        reach.push_back(reach[edge] + (b.pos[edge] - x).norm());
        ch.emplace_back(1, edge);
        auto& pc = ch[p];
        *std::find(pc.begin(), pc.end(), edge) = to;
        b.parent[edge] = to;
      }
      if (to == f) continue;
      auto& fc = ch[f];
      fc.erase(std::find(fc.begin(), fc.end(), c));
      ch[to].push_back(c);
      b.parent[c] = to;
      emptied.push_back(f);
      ++moved;
    }
  }
  // A fork left with one child and no fit of its own was the crotch: onto its stem's axis.
  for (std::uint32_t f : emptied) {
    if (fitted[f] || ch[f].size() != 1 || b.parent[f] == kNone) continue;
    const std::uint32_t p = b.parent[f], c = ch[f][0];
    if (!fitted[p] || !fitted[c]) continue;
    const Eigen::Vector3d pc = b.pos[c] - b.pos[p];
    const double l2 = pc.squaredNorm();
    if (!(l2 > 0)) continue;
    const double t = std::clamp((b.pos[f] - b.pos[p]).dot(pc) / l2, 0.0, 1.0);
    b.pos[f] = b.pos[p] + t * pc;
  }
  if (moved) reorder(b, fitted);
  return moved;
}

}  // namespace ramus::bsg
