#include "reconstruct/bsg/coincident_chains.h"

#include <algorithm>
#include <cmath>

#include "reconstruct/bsg/kdtree.h"

namespace ramus::bsg {

std::size_t join_coincident_chains(Bsg& b, const CoincidentChainParams& params) {
  const std::size_t n = b.size();
  if (n < 3) return 0;
  // `up` is the parent array as it is being changed; it stays a tree rooted at 0 (a node is
  // only ever put between a node it does not descend from and that node's child).
  std::vector<std::uint32_t> up = b.parent;
  double longest = 0;
  for (std::uint32_t v = 1; v < n; ++v) {
    if (up[v] != kNone) longest = std::max(longest, (b.pos[v] - b.pos[up[v]]).norm());
  }
  const PointIndex index(b.pos);  // positions of nodes not joined stay
  auto tolerance = [&](std::uint32_t v) {
    return std::max(params.spacings * params.spacing, params.radius_share * b.radius[v]);
  };
  std::vector<std::uint32_t> near;
  std::size_t joined = 0;
  for (std::uint32_t v = 0; v < n; ++v) {
    const std::uint32_t from = up[v];
    if (from == kNone) continue;
    const Eigen::Vector3d step = b.pos[v] - b.pos[from];
    if (!(step.squaredNorm() > 0)) continue;
    const double ahead = step.norm();
    // Edges are found by their far ends: within the tolerance plus an edge's length of v (a
    // search bound; the walk below bounds how far ahead the edge may lie).
    const double reach = tolerance(v) + std::min(longest, ahead + 4 * tolerance(v));
    near.clear();
    index.within(b.pos[v], reach, near);
    std::sort(near.begin(), near.end());  // ties go to the first node
    std::uint32_t best = kNone;
    double best_d = 0, best_t = 0;
    for (std::uint32_t u : near) {
      // The edge a-u of another chain, processed already.
      const std::uint32_t a = up[u];
      if (u >= v || a == kNone || u == from) continue;
      const Eigen::Vector3d ab = b.pos[u] - b.pos[a];
      const double l2 = ab.squaredNorm();
      if (!(l2 > 0)) continue;
      // Strictly between the edge's ends: v beside an end node is beside that node's other
      // edges as well, and goes on one of those or nowhere (no edge of length zero).
      const double t = (b.pos[v] - b.pos[a]).dot(ab) / l2;
      if (!(t > 0 && t < 1)) continue;
      const double d = (b.pos[a] + t * ab - b.pos[v]).norm();
      const double limit = std::max({tolerance(v), tolerance(u), tolerance(a)});
      if (d > limit || (best != kNone && d >= best_d)) continue;
      if (std::abs(ab.dot(step)) < params.cos_parallel * std::sqrt(l2) * ahead) continue;
      // Ahead of `from` on the tree, by a path no longer than v's own step plus twice the
      // tolerance: a chain that comes back round a loop to v's side is not the one v runs
      // beside. The walk up from a is bounded by that length.
      double walked = 0;
      std::uint32_t x = a;
      while (x != from && up[x] != kNone && walked <= ahead + 2 * limit) {
        walked += (b.pos[x] - b.pos[up[x]]).norm();
        x = up[x];
      }
      if (x != from || walked > ahead + 2 * limit) continue;
      best = u, best_d = d, best_t = t;
    }
    if (best == kNone) continue;
    // v goes onto the edge a-best, between its ends; its own children stay with it.
    const std::uint32_t a = up[best];
    b.pos[v] = b.pos[a] + best_t * (b.pos[best] - b.pos[a]);
    up[v] = a;
    up[best] = v;
    ++joined;
  }
  if (joined == 0) return 0;
  b.parent = up;
  std::vector<std::vector<std::uint32_t>> children = children_of(b.parent);
  b = depth_first(b, children);
  return joined;
}

}  // namespace ramus::bsg
