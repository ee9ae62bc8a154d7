#include "reconstruct/bsg/output.h"

#include <algorithm>
#include <cmath>

#include "core/rng.h"

namespace ramus::bsg {

namespace {

Vec3 to_vec(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }

// An orthonormal turtle frame with the given heading (H x L = U).
void set_frame(Vec3 heading, Vec3& h, Vec3& l, Vec3& u) {
  h = normalized(heading);
  const Vec3 ref = std::abs(h.z) < 0.9 ? Vec3{0, 0, 1} : Vec3{1, 0, 0};
  l = normalized(cross(ref, h));
  u = cross(h, l);
}

// Uniform in the unit ball by rejection (a few draws on average).
Vec3 in_ball(Rng& rng) {
  for (;;) {
    Vec3 p{rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)};
    if (dot(p, p) <= 1.0) return p;
  }
}

// Leaves (4.3, fine geometry synthesis): 20-50 at every leaf node, in a sphere centred on it.
void add_leaves(Skeleton& s, const std::vector<std::vector<std::uint32_t>>& ch,
                const LeafParams& lp) {
  for (std::uint32_t v = 1; v < s.nodes.size(); ++v) {
    if (!ch[v].empty()) continue;
    Rng rng = Rng::stream(lp.seed, lp.tree, v);
    const int span = std::max(0, lp.max_count - lp.min_count);
    const int count = lp.min_count + int(rng.below(std::uint64_t(span) + 1));
    for (int k = 0; k < count; ++k) {
      OrganAnchor a;
      a.node = v;
      a.position = s.nodes[v].position + in_ball(rng) * lp.sphere;
      set_frame(normalized(in_ball(rng), s.nodes[v].heading), a.heading, a.left, a.up);
      a.size = lp.sphere * 0.5;
      a.kind = 0;
      s.organs.push_back(a);
    }
  }
}

}  // namespace

Skeleton to_skeleton(const Bsg& bsg, const Vec3& offset, const LeafParams& leaves) {
  Skeleton s;
  const auto ch = children_of(bsg.parent);
  for (std::uint32_t v = 0; v < bsg.size(); ++v) {
    SkeletonNode n;
    n.position = offset + to_vec(bsg.pos[v]);
    n.radius = std::isfinite(bsg.radius[v]) ? std::max(bsg.radius[v], 0.0) : 0.0;
    n.parent = bsg.parent[v];
    Vec3 heading{0, 0, 1};
    if (n.parent != kNone) {
      heading = to_vec(bsg.pos[v] - bsg.pos[n.parent]);
    } else if (!ch[v].empty()) {
      heading = to_vec(bsg.pos[ch[v][0]] - bsg.pos[v]);
    }
    set_frame(heading, n.heading, n.left, n.up);
    if (n.parent != kNone) {
      // The heaviest child continues its parent's axis; the others start lateral branches.
      const auto& sib = ch[n.parent];
      const std::uint32_t main = *std::max_element(sib.begin(), sib.end(), [&](auto a, auto b) {
        return bsg.weight[a] < bsg.weight[b];
      });
      n.order = std::uint16_t(s.nodes[n.parent].order + (main == v ? 0 : 1));
    }
    s.add(n);
  }
  if (leaves.enabled) add_leaves(s, ch, leaves);
  return s;
}

}  // namespace ramus::bsg
