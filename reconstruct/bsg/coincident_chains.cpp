#include "reconstruct/bsg/coincident_chains.h"

#include <algorithm>
#include <cmath>

#include "reconstruct/bsg/centre_line.h"
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
  // Whether y is x or below it (x an ancestor of y) in the tree as it is being changed.
  auto descends = [&](std::uint32_t x, std::uint32_t y) {
    for (; y != kNone; y = up[y]) {
      if (y == x) return true;
    }
    return false;
  };
  std::vector<std::uint32_t> near;
  // The parents that joined nodes left (tips now, if nothing else hangs there), by old index.
  std::vector<std::uint8_t> left(n, 0);
  std::size_t joined = 0;
  for (std::uint32_t v = 0; v < n; ++v) {
    const std::uint32_t from = up[v];
    if (from == kNone) continue;
    const Eigen::Vector3d step = b.pos[v] - b.pos[from];
    if (!(step.squaredNorm() > 0)) continue;
    const double ahead = step.norm();
    // Edges are found by their far ends, within the tolerance plus an edge's length of v; a
    // search bound of v's own step plus four tolerances for that length is enough, since the
    // chains on one stem were split into steps of about one length (subdivide_long_edges).
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
      if (ab.dot(step) < params.cos_parallel * std::sqrt(l2) * ahead) continue;
      // Not on v's own line of descent: v may not go between two of its ancestors, nor hang
      // from one of its descendants (either would cut the tree into a loop).
      if (descends(u, v) || descends(v, a)) continue;
      best = u, best_d = d, best_t = t;
    }
    if (best == kNone) continue;
    // v goes onto the edge a-best, between its ends; its own children stay with it.
    const std::uint32_t a = up[best];
    b.pos[v] = b.pos[a] + best_t * (b.pos[best] - b.pos[a]);
    // On the stem it takes the stem's radius there: a copy carries the radius of the branch it
    // goes to, or of its own fit, and a node of another radius in the stem's chain is a
    // collar or a neck in its mesh (the 14 m tree of seed 1: 0.30 m among nodes of 0.52 m).
    b.radius[v] = b.radius[a] + best_t * (b.radius[best] - b.radius[a]);
    up[v] = a;
    up[best] = v;
    left[from] = 1;
    ++joined;
  }
  if (joined == 0) return 0;
  b.parent = up;
  std::vector<std::uint32_t> old_of;
  b = depth_first(b, children_of(b.parent), &old_of);
  // What a copy ran along before it came within the tolerance (a path that went down behind its
  // fork and came back up the axis, or ran beside the stem farther than the tolerance) is a leaf
  // chain now; it goes by the rule of drop_branches_inside_stems when it lies inside the wood
  // of the other edges (of the stem it joined, in the cases above).
  std::vector<std::uint8_t> tip_may_go(n);
  for (std::uint32_t v = 0; v < n; ++v) tip_may_go[v] = left[old_of[v]];
  drop_chains_inside_edges(b, std::vector<std::uint8_t>(n, 1), tip_may_go, params.spacing);
  return joined;
}

}  // namespace ramus::bsg
