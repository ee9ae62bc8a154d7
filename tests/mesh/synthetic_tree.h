// Random but plausible skeletons for the mesh tests and the meshing benchmark: a trunk that
// forks into laterals of decreasing radius, with turtle frames, and leaves at the twigs.
#pragma once

#include <cmath>
#include <cstdint>
#include <deque>

#include "core/rng.h"
#include "core/skeleton.h"

namespace ramus::testing {

inline Vec3 random_unit(Rng& rng) {
  for (;;) {
    Vec3 v{rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)};
    const double l = length(v);
    if (l > 0.1 && l <= 1) return v / l;
  }
}

// A node frame with heading h (left perpendicular, up = h x left).
inline void set_frame(SkeletonNode& n, const Vec3& h, Rng& rng) {
  n.heading = normalized(h);
  Vec3 l = cross(Vec3{0, 0, 1}, n.heading);
  if (length(l) < 1e-6) l = Vec3{-1, 0, 0};
  l = normalized(l);
  n.left = l;
  n.up = cross(n.heading, n.left);
}

// About `target` segments (nodes minus roots); same seed, same tree.
inline Skeleton synthetic_tree(std::uint64_t seed, std::size_t target, double leaf_size = 0.3) {
  Rng rng(seed);
  Skeleton s;
  SkeletonNode root;
  root.radius = 0.25;
  set_frame(root, {0, 0, 1}, rng);
  s.add(root);
  // Each tip grows `budget` segments, tapering slowly; laterals start at 0.8 of the parent's
  // radius. At least three segments per lateral keep the branching supercritical, so any
  // target size is reached.
  struct Tip {
    std::uint32_t node;
    Vec3 dir;
    double len;
    int budget;
    double radius;
  };
  std::deque<Tip> open{{0, {0, 0, 1}, 1.0, 12, root.radius}};
  while (!open.empty() && s.nodes.size() <= target) {
    Tip t = open.front();
    open.pop_front();
    for (int k = 0; k < t.budget && s.nodes.size() <= target; ++k) {
      const SkeletonNode& p = s.nodes[t.node];
      SkeletonNode n;
      t.dir = normalized(t.dir + random_unit(rng) * 0.15 + Vec3{0, 0, 0.05});
      n.position = p.position + t.dir * t.len;
      n.radius = k == 0 ? t.radius : p.radius * 0.985;
      n.parent = t.node;
      set_frame(n, t.dir, rng);
      const std::uint32_t id = s.add(n);
      if (rng.uniform01() < 0.45 && n.radius > 1e-4) {
        const Vec3 side = normalized(t.dir + random_unit(rng) * 1.2);
        open.push_back(
            {id, side, std::max(t.len * 0.85, 0.1), std::max(3, t.budget - 2), n.radius * 0.8});
      }
      t.node = id;
    }
    OrganAnchor leaf;
    leaf.node = t.node;
    leaf.position = s.nodes[t.node].position;
    leaf.heading = normalized(t.dir + Vec3{0, 0, 0.3});
    leaf.left = s.nodes[t.node].left;
    leaf.up = cross(leaf.heading, leaf.left);
    leaf.size = leaf_size;
    s.organs.push_back(leaf);
  }
  // Laterals: a child whose direction differs from the parent's chain gets order + 1.
  const auto ch = s.children();
  for (std::uint32_t i = 0; i < s.nodes.size(); ++i) {
    bool first = true;
    for (const std::uint32_t* c = ch.begin(i); c != ch.end(i); ++c) {
      s.nodes[*c].order = std::uint16_t(s.nodes[i].order + (first ? 0 : 1));
      first = false;
    }
  }
  return s;
}

}  // namespace ramus::testing
