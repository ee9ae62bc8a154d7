// Branch merging (thesis draft section 4.3.2): Alg. 6 (vertical merge of nearly collinear chains)
// and Alg. 7 (horizontal merge of sibling leaf branches) on a mutable child-list view of the
// skeleton, then compaction back into a Skeleton whose parents precede their children.
#include "reconstruct/merge/branch_merge.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace ramus::merge {

namespace {

constexpr double kPi = 3.14159265358979323846;

// gamma = acos(u.v / (|u||v|)) of Alg. 6 line 5 and Alg. 7 line 7, in degrees. A zero-length
// vector has no direction; it counts as angle 0 so coincident nodes always merge.
double angle_deg(const Vec3& u, const Vec3& v) {
  const double lu = length(u), lv = length(v);
  if (!(lu > 0) || !(lv > 0)) return 0.0;
  const double c = std::clamp(dot(u, v) / (lu * lv), -1.0, 1.0);
  return std::acos(c) * 180.0 / kPi;
}

// Re-orthonormalizes a node's frame around a new heading, keeping its left vector as close to
// the old one as possible so the bark texture does not twist.
void reframe(SkeletonNode& n, const Vec3& heading) {
  const Vec3 h = normalized(heading, n.heading);
  Vec3 l = n.left - h * dot(n.left, h);
  if (length(l) < 1e-9) {
    const Vec3 ref = std::abs(h.z) < 0.9 ? Vec3{0, 0, 1} : Vec3{1, 0, 0};
    l = cross(ref, h);
  }
  l = normalized(l);
  n.heading = h;
  n.left = l;
  n.up = cross(h, l);
}

// The skeleton as editable child lists. Removed nodes keep their slot (alive = false) until
// compaction, so indices stay stable while the algorithms run.
struct Editable {
  std::vector<SkeletonNode> nodes;
  std::vector<std::vector<std::uint32_t>> children;
  std::vector<std::uint8_t> alive;
  std::vector<std::uint32_t> absorbed_by;  // removed node -> node its organs move to
  MergeStats stats;
};

// Alg. 6 from node n. The pseudocode walks each chain n -> n' -> n'' ... while n' has a single
// child and removes n' when the turn at n' is below alpha. When a node is kept, the chain's
// anchor moves to it (the next turn is measured at the following node, from the kept one), and
// the recursion continues from the node that ends the chain, so a root with a single trunk is
// processed too (the pseudocode's line 13 would stop there).
void vertical_merge(Editable& e, std::uint32_t root, double alpha) {
  std::vector<std::uint32_t> stack{root};
  while (!stack.empty()) {
    const std::uint32_t n = stack.back();
    stack.pop_back();
    for (std::size_t k = 0; k < e.children[n].size(); ++k) {
      std::uint32_t anchor = n;
      std::uint32_t cur = e.children[n][k];
      while (e.children[cur].size() == 1) {
        const std::uint32_t next = e.children[cur][0];
        const Vec3 u = e.nodes[cur].position - e.nodes[anchor].position;
        const Vec3 v = e.nodes[next].position - e.nodes[cur].position;
        if (angle_deg(u, v) < alpha) {
          // Lines 7-8: the anchor adopts n'' in the place of n'.
          auto& siblings = e.children[anchor];
          *std::find(siblings.begin(), siblings.end(), cur) = next;
          e.nodes[next].parent = anchor;
          reframe(e.nodes[next], e.nodes[next].position - e.nodes[anchor].position);
          e.alive[cur] = 0;
          e.absorbed_by[cur] = next;
          e.children[cur].clear();
          ++e.stats.vertical_merges;
        } else {
          anchor = cur;
        }
        cur = next;  // line 10
      }
      stack.push_back(cur);
    }
  }
}

// Alg. 7 at node n: the first pair of leaf children (in child order) closer than beta becomes one
// leaf at their midpoint with the larger radius; then the node is examined again (line 15) until
// no pair merges, and the children are processed in turn (lines 19-21).
void horizontal_merge(Editable& e, std::uint32_t root, double beta) {
  std::vector<std::uint32_t> stack{root};
  while (!stack.empty()) {
    const std::uint32_t n = stack.back();
    stack.pop_back();
    bool merged = true;
    while (merged) {
      merged = false;
      auto& ch = e.children[n];
      for (std::size_t i = 0; i < ch.size() && !merged; ++i) {
        for (std::size_t j = i + 1; j < ch.size() && !merged; ++j) {
          const std::uint32_t n1 = ch[i], n2 = ch[j];
          if (!e.children[n1].empty() || !e.children[n2].empty()) continue;
          const Vec3 u = e.nodes[n1].position - e.nodes[n].position;
          const Vec3 v = e.nodes[n2].position - e.nodes[n].position;
          if (!(angle_deg(u, v) < beta)) continue;
          // Lines 9-14. The new leaf takes n1's slot, so node order and parents-first hold.
          SkeletonNode merged_node = e.nodes[n1];
          merged_node.position = (e.nodes[n1].position + e.nodes[n2].position) * 0.5;
          merged_node.radius = std::max(e.nodes[n1].radius, e.nodes[n2].radius);
          reframe(merged_node, merged_node.position - e.nodes[n].position);
          e.nodes[n1] = merged_node;
          e.alive[n2] = 0;
          e.absorbed_by[n2] = n1;
          ch.erase(ch.begin() + std::ptrdiff_t(j));
          ++e.stats.horizontal_merges;
          merged = true;
        }
      }
    }
    for (std::uint32_t c : e.children[n]) stack.push_back(c);
  }
}

// Node order in which every parent precedes its children: the input order when it already is,
// else a depth-first order from the roots.
std::vector<std::uint32_t> parents_first_order(const Skeleton& s) {
  std::vector<std::uint32_t> order(s.size());
  bool sorted = true;
  for (std::uint32_t i = 0; i < s.size(); ++i) {
    order[i] = i;
    if (s.nodes[i].parent != kNoParent && s.nodes[i].parent >= i) sorted = false;
  }
  if (sorted) return order;
  order.clear();
  const Skeleton::Children ch = s.children();
  std::vector<std::uint32_t> stack;
  const std::vector<std::uint32_t> roots = s.roots();
  for (auto it = roots.rbegin(); it != roots.rend(); ++it) stack.push_back(*it);
  while (!stack.empty()) {
    const std::uint32_t v = stack.back();
    stack.pop_back();
    order.push_back(v);
    for (auto c = ch.end(v); c != ch.begin(v);) stack.push_back(*--c);
  }
  return order;
}

}  // namespace

MergeStats merge_branches(Skeleton& s, const MergeOptions& o) {
  if (!std::isfinite(o.alpha_deg) || !std::isfinite(o.beta_deg) || o.alpha_deg < 0 ||
      o.beta_deg < 0) {
    throw std::invalid_argument("merge angles must be finite and non-negative (got alpha " +
                                std::to_string(o.alpha_deg) + ", beta " +
                                std::to_string(o.beta_deg) + ")");
  }
  const std::string problem = s.validate();
  if (!problem.empty()) throw std::invalid_argument("cannot merge an invalid skeleton: " + problem);

  // Work in a parents-first order so that compaction keeps it.
  const std::vector<std::uint32_t> order = parents_first_order(s);
  std::vector<std::uint32_t> rank(s.size());
  for (std::uint32_t i = 0; i < order.size(); ++i) rank[order[i]] = i;
  Editable e;
  e.stats.nodes_before = s.size();
  e.nodes.reserve(s.size());
  for (std::uint32_t v : order) {
    SkeletonNode n = s.nodes[v];
    if (n.parent != kNoParent) n.parent = rank[n.parent];
    e.nodes.push_back(n);
  }
  e.children.assign(e.nodes.size(), {});
  e.alive.assign(e.nodes.size(), 1);
  e.absorbed_by.assign(e.nodes.size(), kNoParent);
  std::vector<std::uint32_t> roots;
  for (std::uint32_t i = 0; i < e.nodes.size(); ++i) {
    if (e.nodes[i].parent == kNoParent) {
      roots.push_back(i);
    } else {
      e.children[e.nodes[i].parent].push_back(i);
    }
  }

  for (std::uint32_t r : roots) vertical_merge(e, r, o.alpha_deg);
  for (std::uint32_t r : roots) horizontal_merge(e, r, o.beta_deg);

  // Compaction: surviving nodes keep their relative order.
  std::vector<std::uint32_t> remap(e.nodes.size(), kNoParent);
  Skeleton out;
  out.organ_kinds = s.organ_kinds;
  for (std::uint32_t i = 0; i < e.nodes.size(); ++i) {
    if (!e.alive[i]) continue;
    remap[i] = std::uint32_t(out.nodes.size());
    SkeletonNode n = e.nodes[i];
    if (n.parent != kNoParent) n.parent = remap[n.parent];
    out.nodes.push_back(n);
  }
  for (OrganAnchor a : s.organs) {
    std::uint32_t v = rank[a.node];
    while (!e.alive[v]) v = e.absorbed_by[v];
    a.node = remap[v];
    out.organs.push_back(a);
  }
  e.stats.nodes_after = out.size();
  s = std::move(out);
  return e.stats;
}

}  // namespace ramus::merge
