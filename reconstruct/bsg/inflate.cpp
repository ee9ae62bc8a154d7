// Section 4.3 of Livny et al. 2010.
#include "reconstruct/bsg/inflate.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "reconstruct/bsg/bsg.h"
#include "reconstruct/bsg/refine.h"
#include "reconstruct/bsg/sample_distance.h"

namespace ramus::bsg {

namespace {

// A generalized cylinder: a segment with linearly varying radius, closed by the balls at its
// ends so that the cylinders of a chain join without gaps.
struct Cylinder {
  Eigen::Vector3d a, b;
  double ra, rb;
  bool contains(const Eigen::Vector3d& p) const {
    const Eigen::Vector3d ab = b - a;
    const double l2 = ab.squaredNorm();
    const double t = l2 > 0 ? std::clamp((p - a).dot(ab) / l2, 0.0, 1.0) : 0.0;
    const double r = ra + t * (rb - ra);
    return (p - (a + t * ab)).squaredNorm() <= r * r;
  }
};

// The sample pattern of covers_more_than: on each of 4 cross-sections the centre and two rings
// of 6 (radii sqrt(1/4), sqrt(3/4) of the radius: equal areas, the outer ring turned by 30
// degrees), as unit offsets in the cross-section's frame, computed once.
struct CoverPattern {
  static constexpr std::array<double, 4> kT = {0.125, 0.375, 0.625, 0.875};
  static constexpr int kPerSection = 13;
  std::array<double, kPerSection> ring{}, cos{}, sin{};  // entry 0 is the centre
  CoverPattern() {
    static constexpr std::array<double, 2> kR = {0.5, 0.866};
    int s = 1;
    for (double rr : kR) {
      for (int k = 0; k < 6; ++k, ++s) {
        const double ang = (k + 0.5 * (rr > 0.6)) * (M_PI / 3);
        ring[s] = rr, cos[s] = std::cos(ang), sin[s] = std::sin(ang);
      }
    }
  }
};

// Whether more than `overlap` of the volume of `c` (its straight part) lies inside any of
// `others`, estimated on a fixed, volume-uniform pattern of 52 samples so that the result is
// deterministic. The count stops as soon as the answer is settled either way: inflation asks
// this for every short edge in every round, and most answers are clear after a few samples.
bool covers_more_than(const Cylinder& c, const std::vector<Cylinder>& others, double overlap) {
  if (others.empty()) return 0.0 > overlap;
  const Eigen::Vector3d axis = c.b - c.a;
  const double len = axis.norm();
  if (len <= 0) return 1.0 > overlap;
  static const CoverPattern pattern;
  const Eigen::Vector3d d = axis / len;
  Eigen::Vector3d e1, e2;
  perpendicular_frame(d, e1, e2);
  constexpr int total = int(CoverPattern::kT.size()) * CoverPattern::kPerSection;
  // The fraction inside/total is compared exactly as a full count would be.
  auto more = [&](int inside) { return double(inside) / double(total) > overlap; };
  int inside = 0, tested = 0;
  for (double t : CoverPattern::kT) {
    const Eigen::Vector3d centre = c.a + t * axis;
    const double r = c.ra + t * (c.rb - c.ra);
    for (int s = 0; s < CoverPattern::kPerSection; ++s) {
      const Eigen::Vector3d p =
          s == 0 ? centre
                 : Eigen::Vector3d(centre + r * pattern.ring[s] *
                                                (pattern.cos[s] * e1 + pattern.sin[s] * e2));
      ++tested;
      for (const Cylinder& o : others) {
        if (o.contains(p)) {
          ++inside;
          break;
        }
      }
      if (more(inside)) return true;
      if (!more(inside + total - tested)) return false;
    }
  }
  return more(inside);
}

// A mutable view of the BSG while edges are collapsed.
struct Editable {
  Bsg& b;
  std::vector<std::vector<std::uint32_t>> ch;
  std::vector<std::uint8_t> alive;

  // The cylinder of edge (u, v), v the child, has v's radius: the edge is v's segment, and a
  // thin twig leaving a thick trunk must not inherit the trunk's radius at its start.
  // Radii below the voxel size are raised to it: the merged points cannot resolve finer
  // detail, and zig-zags of one voxel across a thin branch must cluster away.
  Cylinder cyl(std::uint32_t u, std::uint32_t v) const {
    const double r = std::max(b.radius[v], min_radius);
    return {b.pos[u], b.pos[v], r, r};
  }
  double min_radius = 0;
  double tolerance = 0;  // a degree-2 collapse may move the branch by this much at least
  // Per vertex: the positions of the vertices its degree-2 collapses took in, over every round
  // (null: only the two current positions are checked). Only degree-2 collapses record: the
  // shape check is theirs, and recording the edge removals' merges too (in merge()) measured
  // worse on the harness (the 14 m tree from one station at 0 degrees recall 0.933 -> 0.916,
  // the weeping tree from three 0.960 / 0.962 -> 0.957 / 0.959).
  std::vector<std::vector<Eigen::Vector3d>>* absorbed = nullptr;
  // Collapses edge (u, a), a a child of u, into u at the weighted midpoint (4.3).
  void merge(std::uint32_t u, std::uint32_t a, bool keep_a_position = false) {
    // The midpoint is weighted by the points each vertex stands for, so a merged vertex is the
    // centroid of its cluster. (The paper weights by c; on samples that lie on the bark this
    // lets a vertex walk along a heavy branch, one collapse at a time.)
    const double mu = b.mass[u], ma = b.mass[a];
    if (keep_a_position) {
      b.pos[u] = b.pos[a];
    } else if (b.parent[u] != kNone) {
      // The root stays where the base was found.
      b.pos[u] = (mu * b.pos[u] + ma * b.pos[a]) / std::max(mu + ma, 1e-300);
    }
    b.mass[u] = mu + ma;
    auto& cu_list = ch[u];
    cu_list.erase(std::find(cu_list.begin(), cu_list.end(), a));
    for (std::uint32_t g : ch[a]) b.parent[g] = u, cu_list.push_back(g);
    ch[a].clear();
    alive[a] = 0;
    b.vertex[u] = kNone;
  }
};

// How far one pass of edge removal may move a fork, in its radii (at least min_radius).
// Each merge moves u to the weighted midpoint (4.3); a fork whose parent edge is in line with
// a non-heavy child walks along that child merge by merge, because the parent's cylinder
// stretches with u and covers the next edge too. The weeping example from one station at 300
// degrees: the fork of a 14 cm limb walked 0.55 m along its lighter branch in one pass, and the
// heavier branch hung from the far end (10-20 cm class 0.433 r over the seen wood). A tenth of
// the radius keeps the clustering of a fork's short spurs and stops the walk.
constexpr double kForkDrift = 0.1;

// Edge removal: a child edge of u covered by the other cylinders meeting at u.
std::size_t remove_covered(Editable& e, std::uint32_t u, double overlap) {
  std::size_t merged = 0;
  const Eigen::Vector3d origin = e.b.pos[u];
  const double drift = kForkDrift * std::max(e.b.radius[u], e.min_radius);
  for (bool again = true; again;) {
    again = false;
    // The heaviest child continues the branch through u; only the others can be negligible.
    std::uint32_t main = kNone;
    for (std::uint32_t a : e.ch[u]) {
      if (main == kNone || e.b.weight[a] > e.b.weight[main]) main = a;
    }
    for (std::uint32_t a : e.ch[u]) {
      if (a == main && e.b.parent[u] != kNone) continue;
      // Only short edges cluster: a long edge alongside a sibling is a branch of its own, and
      // merging it would drag u far from where its points are.
      const double reach = 2 * std::max(e.b.radius[u], e.min_radius);
      if ((e.b.pos[a] - e.b.pos[u]).squaredNorm() > reach * reach) continue;
      std::vector<Cylinder> others;
      if (e.b.parent[u] != kNone) others.push_back(e.cyl(e.b.parent[u], u));
      for (std::uint32_t s : e.ch[u]) {
        if (s != a) others.push_back(e.cyl(u, s));
      }
      if (covers_more_than(e.cyl(u, a), others, overlap)) {
        e.merge(u, a);
        const Eigen::Vector3d moved = e.b.pos[u] - origin;
        if (moved.norm() > drift) e.b.pos[u] = origin + moved * (drift / moved.norm());
        ++merged;
        again = true;
        break;
      }
    }
  }
  return merged;
}

// Whether replacing v and w by one vertex at `merged` keeps the branch where its samples are:
// both old positions stay within `tolerance` of the new polyline u -> merged -> w's children.
// Without this, a run of collapses along a curved branch (a weeping whip, an arching limb)
// replaces the curve by its chord, which leaves the points it stands for.
bool collapse_keeps_shape(const Editable& e, std::uint32_t u, std::uint32_t v, std::uint32_t w,
                          const Eigen::Vector3d& merged, double tolerance) {
  auto near = [&](const Eigen::Vector3d& old) {
    double d = point_segment_distance(old, e.b.pos[u], merged);
    for (std::uint32_t x : e.ch[w])
      d = std::min(d, point_segment_distance(old, merged, e.b.pos[x]));
    return d <= tolerance;
  };
  if (!near(e.b.pos[v]) || !near(e.b.pos[w])) return false;
  if (e.absorbed) {
    for (std::uint32_t x : {v, w})
      for (const Eigen::Vector3d& old : (*e.absorbed)[x])
        if (!near(old)) return false;
  }
  return true;
}

// Degree-2 collapse: v with parent u and one child w; (v, w) goes when the extension of (u, v)
// beyond v covers more than half of it. Tips are kept so that branches keep their length.
std::size_t collapse_degree2(Editable& e, std::uint32_t v, double overlap) {
  std::size_t merged = 0;
  while (e.b.parent[v] != kNone && e.ch[v].size() == 1 && !e.ch[e.ch[v][0]].empty()) {
    const std::uint32_t u = e.b.parent[v], w = e.ch[v][0];
    const Eigen::Vector3d ext = e.b.pos[v] + (e.b.pos[v] - e.b.pos[u]);
    const double rv = std::max(e.b.radius[v], e.min_radius);
    const Cylinder virt{e.b.pos[v], ext, rv, rv};
    if (!covers_more_than(e.cyl(v, w), {virt}, overlap)) break;
    // A branching w keeps its place (v simply disappears from a straight run); otherwise
    // branch points would creep down the trunk one collapse at a time.
    const bool keep_w = e.ch[w].size() != 1;
    const double mv = e.b.mass[v], mw = e.b.mass[w];
    const Eigen::Vector3d target =
        keep_w ? e.b.pos[w]
               : Eigen::Vector3d((mv * e.b.pos[v] + mw * e.b.pos[w]) / std::max(mv + mw, 1e-300));
    if (!collapse_keeps_shape(e, u, v, w, target, std::max(e.b.radius[v], e.tolerance))) break;
    if (e.absorbed) {
      auto& av = (*e.absorbed)[v];
      auto& aw = (*e.absorbed)[w];
      av.push_back(e.b.pos[v]), av.push_back(e.b.pos[w]);
      av.insert(av.end(), aw.begin(), aw.end());
      aw.clear();
    }
    e.merge(v, w, keep_w);
    ++merged;
  }
  return merged;
}

// Re-indexes the surviving vertices in parent-first order.
void compact(Editable& e) {
  std::vector<std::uint32_t> old_of;
  e.b = depth_first(e.b, e.ch, &old_of);
  if (!e.absorbed) return;
  std::vector<std::vector<Eigen::Vector3d>> moved(old_of.size());
  for (std::size_t i = 0; i < old_of.size(); ++i) moved[i] = std::move((*e.absorbed)[old_of[i]]);
  *e.absorbed = std::move(moved);
}

}  // namespace

// Eq. 6 asks r_parent = k r_child on every edge with k = (c_parent / c_child)^(1/exponent) (the
// pipe-model reading of Eq. 5: r^2.5 proportional to the subtree weight). On a tree these n - 1
// homogeneous equations have a one-dimensional solution space, r = s * r0 with r0 propagated
// from the root; Eq. 7 (sum c_v r_v = d_avg sum c_v) then fixes s. Both terms reach zero, so
// this closed form is the exact minimizer of Eq. 6 + Eq. 7.
void assign_radii(Bsg& bsg, double d_avg, double exponent, double root_radius) {
  const std::size_t n = bsg.size();
  bsg.radius.assign(n, 1.0);
  for (std::size_t v = 1; v < n; ++v) {
    const std::uint32_t p = bsg.parent[v];
    const double ratio = bsg.weight[v] / std::max(bsg.weight[p], 1e-300);
    bsg.radius[v] = bsg.radius[p] * std::pow(std::min(ratio, 1.0), 1.0 / exponent);
  }
  double cr = 0, c = 0;
  for (std::size_t v = 0; v < n; ++v) cr += bsg.weight[v] * bsg.radius[v], c += bsg.weight[v];
  const double s = root_radius > 0 ? root_radius : (cr > 0 ? d_avg * c / cr : 0.0);
  for (double& r : bsg.radius) r *= s;
}

std::size_t collapse_overlaps(Bsg& bsg, double overlap, double min_radius, double tolerance,
                              std::vector<std::vector<Eigen::Vector3d>>* absorbed) {
  if (bsg.size() < 2) return 0;
  Editable e{bsg, children_of(bsg.parent), std::vector<std::uint8_t>(bsg.size(), 1)};
  e.min_radius = min_radius;
  e.tolerance = tolerance;
  if (absorbed && absorbed->size() == bsg.size()) e.absorbed = absorbed;
  std::size_t merged = 0;
  for (std::uint32_t u = 0; u < bsg.size(); ++u) {
    if (!e.alive[u]) continue;
    merged += remove_covered(e, u, overlap);
    merged += collapse_degree2(e, u, overlap);
  }
  if (merged) compact(e);
  return merged;
}

std::size_t prune_twigs(Bsg& bsg, double min_length) {
  if (bsg.size() < 2 || min_length <= 0) return 0;
  Editable e{bsg, children_of(bsg.parent), std::vector<std::uint8_t>(bsg.size(), 1)};
  std::size_t removed = 0;
  for (std::uint32_t leaf = std::uint32_t(bsg.size()); leaf-- > 1;) {
    if (!e.alive[leaf] || !e.ch[leaf].empty()) continue;
    // Walk down to the branching vertex the twig leaves from.
    double len = 0;
    std::uint32_t v = leaf;
    while (bsg.parent[v] != kNone && e.ch[bsg.parent[v]].size() == 1 && len < min_length) {
      len += (bsg.pos[v] - bsg.pos[bsg.parent[v]]).norm();
      v = bsg.parent[v];
    }
    const std::uint32_t fork = bsg.parent[v];
    if (fork == kNone || len + (bsg.pos[v] - bsg.pos[fork]).norm() >= min_length) continue;
    auto& sib = e.ch[fork];
    sib.erase(std::find(sib.begin(), sib.end(), v));
    for (std::uint32_t w = leaf;; w = bsg.parent[w]) {
      e.alive[w] = 0;
      ++removed;
      if (w == v) break;
    }
  }
  if (removed) compact(e);
  return removed;
}

int inflate(Bsg& bsg, const std::vector<Eigen::Vector3d>& samples,
            const std::vector<std::uint32_t>& counts, const InflateParams& params) {
  int rounds = 0;
  // The mean sample distance of the BSG as it stands, when the last round computed it and
  // nothing moved since (it depends on the positions and edges only): -1 otherwise.
  double d_current = -1;
  // Collapsing moves vertices towards the branch axes, which raises d_avg, which widens the
  // cylinders; the loop runs to the fixed point where nothing more collapses (4.3).
  std::vector<std::vector<Eigen::Vector3d>> absorbed(bsg.size());
  SampleDistances distances(samples, params.edge_sample);
  for (; rounds < 40; ++rounds) {
    importance_weights(bsg, params.own_weight);
    const double d_avg = params.root_radius > 0 ? 0.0 : distances.mean(bsg, counts);
    assign_radii(bsg, d_avg, params.exponent, params.root_radius);
    d_current = params.root_radius > 0 ? -1 : d_avg;
    if (collapse_overlaps(bsg, params.overlap, params.min_radius, params.tolerance, &absorbed) == 0)
      break;
    d_current = -1;
  }
  if (prune_twigs(bsg, params.min_twig) > 0) d_current = -1;
  importance_weights(bsg, params.own_weight);
  // With a measured root radius d_avg is not used (assign_radii), and not computed.
  const double d_final = params.root_radius > 0 ? 0.0
                         : d_current >= 0       ? d_current
                                                : distances.mean(bsg, counts);
  assign_radii(bsg, d_final, params.exponent, params.root_radius);
  return rounds;
}

}  // namespace ramus::bsg
