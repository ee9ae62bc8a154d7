#include "reconstruct/bsg/tip_extension.h"

#include <algorithm>
#include <cmath>

namespace ramus::bsg {

std::size_t extend_tips(Bsg& b, const std::vector<Eigen::Vector3d>& samples,
                        const PointIndex& index, const TipExtensionParams& p) {
  if (b.size() < 2 || samples.empty()) return 0;
  const double s = p.spacing;
  // The edges as they are before any tip moves, sampled every half voxel, each sample knowing
  // its edge (the child node's index): a sample ahead of a tip is claimed by the edge nearest it.
  std::vector<Eigen::Vector3d> along;
  std::vector<std::uint32_t> owner;
  for (std::uint32_t v = 1; v < b.size(); ++v) {
    const std::uint32_t u = b.parent[v];
    if (u == kNone) continue;
    const Eigen::Vector3d a = b.pos[u], c = b.pos[v];
    const int steps = std::clamp(int(std::ceil((c - a).norm() / (0.5 * s))), 1, 100000);
    for (int k = 0; k <= steps; ++k) {
      along.push_back(a + (c - a) * (double(k) / steps));
      owner.push_back(v);
    }
  }
  if (along.empty()) return 0;
  const PointIndex edges(along);
  const std::vector<std::vector<std::uint32_t>> children = children_of(b.parent);
  std::vector<std::uint32_t> near;
  std::vector<std::pair<double, std::uint32_t>> ahead;  // (distance ahead, sample)
  std::size_t moved_tips = 0;
  for (std::uint32_t v = 1; v < b.size(); ++v) {
    if (!children[v].empty() || b.parent[v] == kNone) continue;
    // The direction over the last few voxels of the chain, not the last edge alone.
    std::uint32_t back = b.parent[v];
    while (b.parent[back] != kNone && (b.pos[v] - b.pos[back]).norm() < p.direction_back * s)
      back = b.parent[back];
    Eigen::Vector3d d = b.pos[v] - b.pos[back];
    if (d.norm() < 1e-12) continue;
    d.normalize();
    const double width = std::max(b.radius[v], s);
    Eigen::Vector3d c = b.pos[v];
    double moved = 0;
    while (moved < p.max_length * s) {
      near.clear();
      index.within(c, p.reach * s, near);
      double t_max = 0;
      ahead.clear();
      for (std::uint32_t i : near) {
        const Eigen::Vector3d w = samples[i] - c;
        const double t = w.dot(d);
        if (t <= 0.5 * s || (w - t * d).norm() > width + p.cone * t) continue;
        double d2;
        const std::uint32_t e = owner[edges.nearest(samples[i], &d2)];
        if (e != v && std::sqrt(d2) <= std::max(b.radius[e], s)) continue;  // another branch's
        ahead.emplace_back(t, i);
        t_max = std::max(t_max, t);
      }
      if (ahead.empty()) break;
      // The centroid of the farthest voxel's layer: the branch's axis there, not its bark.
      Eigen::Vector3d sum = Eigen::Vector3d::Zero();
      int n = 0;
      for (const auto& [t, i] : ahead) {
        if (t >= t_max - s) sum += samples[i], ++n;
      }
      const Eigen::Vector3d next = sum / n;
      const Eigen::Vector3d step = next - c;
      const double len = step.norm();
      if (len < 0.5 * s || step.dot(d) <= 0) break;
      moved += len;
      d = (d + step / len).normalized();
      c = next;
    }
    // The tip moves to where the walk ended: its edge stays one internode, as the branch's last
    // internode is one (a node per step, or one new node, changed the internode statistics the
    // scaffold inference takes from the skeleton: docs/reconstruction.md, step 7).
    if (moved > 0) b.pos[v] = c, ++moved_tips;
  }
  return moved_tips;
}

}  // namespace ramus::bsg
