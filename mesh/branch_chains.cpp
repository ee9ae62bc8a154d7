#include "mesh/branch_chains.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace ramus::mesh {
namespace {

std::string where(const char* what, std::size_t i) {
  return std::string(what) + " " + std::to_string(i);
}

bool finite_frame(const Vec3& h, const Vec3& l, const Vec3& u) {
  return is_finite(h) && is_finite(l) && is_finite(u);
}

// Rejects values no repair can give meaning to: NaN/inf anywhere, parents out of range, cycles.
void check_values(const Skeleton& s) {
  const std::size_t n = s.nodes.size();
  for (std::size_t i = 0; i < n; ++i) {
    const SkeletonNode& node = s.nodes[i];
    if (!is_finite(node.position)) throw MeshError(where("node", i) + " has a non-finite position");
    if (!std::isfinite(node.radius)) throw MeshError(where("node", i) + " has a non-finite radius");
    if (!finite_frame(node.heading, node.left, node.up)) {
      throw MeshError(where("node", i) + " has a non-finite frame");
    }
    if (node.parent != kNoParent && node.parent >= n) {
      throw MeshError(where("node", i) + " has parent " + std::to_string(node.parent) +
                      " out of range");
    }
  }
  for (std::size_t i = 0; i < s.organs.size(); ++i) {
    const OrganAnchor& o = s.organs[i];
    if (!is_finite(o.position) || !std::isfinite(o.size) ||
        !finite_frame(o.heading, o.left, o.up)) {
      throw MeshError(where("organ", i) + " has a non-finite position, size or frame");
    }
    for (const Vec3& v : o.vertices) {
      if (!is_finite(v)) throw MeshError(where("organ", i) + " has a non-finite polygon vertex");
    }
    if (o.node != kNoParent && o.node >= n)
      throw MeshError(where("organ", i) + " hangs from a node out of range");
  }
}

// Nodes in an order where every parent comes before its children; throws on cycles.
std::vector<std::uint32_t> topological_order(const Skeleton& s, const Skeleton::Children& ch) {
  std::vector<std::uint32_t> order;
  order.reserve(s.nodes.size());
  for (std::uint32_t r : s.roots()) order.push_back(r);
  for (std::size_t k = 0; k < order.size(); ++k) {
    for (const std::uint32_t* c = ch.begin(order[k]); c != ch.end(order[k]); ++c)
      order.push_back(*c);
  }
  if (order.size() != s.nodes.size()) {
    throw MeshError("the skeleton's parent links form a cycle (" +
                    std::to_string(s.nodes.size() - order.size()) + " nodes never reach a root)");
  }
  return order;
}

// Pipe model (Shinozaki et al. 1964; MacDonald 1983): r_parent^e = sum r_child^e, tips keep their
// own radius. Evaluated children-first along the reversed topological order.
void apply_pipe_model(const Skeleton::Children& ch, const std::vector<std::uint32_t>& topo,
                      double e, std::vector<double>& r) {
  for (auto it = topo.rbegin(); it != topo.rend(); ++it) {
    const std::uint32_t i = *it;
    if (ch.count(i) == 0) continue;
    double sum = 0;
    for (const std::uint32_t* c = ch.begin(i); c != ch.end(i); ++c) sum += std::pow(r[*c], e);
    r[i] = std::pow(sum, 1.0 / e);
  }
}

std::uint32_t continuation(const Skeleton& s, const Skeleton::Children& ch,
                           const std::vector<double>& r, std::uint32_t i) {
  std::uint32_t best = kNoParent;
  for (const std::uint32_t* c = ch.begin(i); c != ch.end(i); ++c) {
    if (best == kNoParent || s.nodes[*c].order < s.nodes[best].order ||
        (s.nodes[*c].order == s.nodes[best].order && r[*c] > r[best])) {
      best = *c;
    }
  }
  return best;
}

// Walks every chain with an explicit stack (skeletons can be millions of nodes deep).
void build_chains(const Skeleton& s, const Skeleton::Children& ch, PreparedSkeleton& p) {
  struct Start {
    std::uint32_t from, first, parent_chain;
  };
  std::vector<Start> stack;
  const auto roots = s.roots();
  for (auto it = roots.rbegin(); it != roots.rend(); ++it)
    stack.push_back({kNoParent, *it, kNoChain});
  p.chain_of_node.assign(s.nodes.size(), kNoChain);
  std::vector<std::uint32_t> laterals;
  while (!stack.empty()) {
    Start st = stack.back();
    stack.pop_back();
    const std::uint32_t id = std::uint32_t(p.chains.size());
    Chain chain;
    chain.parent_chain = st.parent_chain;
    chain.order = s.nodes[st.first].order;
    if (st.from != kNoParent) chain.nodes.push_back(st.from);
    laterals.clear();
    for (std::uint32_t v = st.first; v != kNoParent;) {
      chain.nodes.push_back(v);
      p.chain_of_node[v] = id;
      const std::uint32_t next = continuation(s, ch, p.radius, v);
      for (const std::uint32_t* c = ch.begin(v); c != ch.end(v); ++c) {
        if (*c != next) laterals.push_back(*c);
      }
      v = next;
    }
    p.chains.push_back(std::move(chain));
    for (auto it = laterals.rbegin(); it != laterals.rend(); ++it) {
      stack.push_back({s.nodes[*it].parent, *it, id});
    }
  }
}

}  // namespace

PreparedSkeleton prepare_skeleton(const Skeleton& s, const MeshOptions& options,
                                  MeshReport& report) {
  check_values(s);
  PreparedSkeleton p;
  const auto ch = s.children();
  const auto topo = topological_order(s, ch);
  s.bounds(p.lo, p.hi);
  p.extent = distance(p.lo, p.hi);
  const double floor =
      options.min_radius > 0 ? options.min_radius : std::max(p.extent * 1e-4, 1e-9);
  report.min_radius = p.min_radius = floor;
  p.radius.resize(s.nodes.size());
  bool any_radius = false;
  for (std::size_t i = 0; i < s.nodes.size(); ++i) {
    p.radius[i] = s.nodes[i].radius;
    any_radius = any_radius || s.nodes[i].radius > 0;
  }
  double exponent = options.pipe_exponent;
  if (!any_radius && !s.nodes.empty()) {
    // A grammar that never sets a width: thin tips thickening toward the base read as a tree.
    report.radii_synthesized = true;
    exponent = exponent > 0 ? exponent : 2.0;
    std::fill(p.radius.begin(), p.radius.end(), std::max(p.extent * 2e-3, floor));
  }
  for (double& r : p.radius) {
    if (r < floor) {
      r = floor;
      ++report.clamped_radii;
    }
  }
  if (exponent > 0) apply_pipe_model(ch, topo, exponent, p.radius);
  for (double r : p.radius) p.max_radius = std::max(p.max_radius, r);
  build_chains(s, ch, p);
  return p;
}

}  // namespace ramus::mesh
