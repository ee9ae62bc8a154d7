#include "reconstruct/forest/core_trees.h"

#include <algorithm>

namespace ramus::forest {

CoreTrees keep_core_trees(const std::vector<Skeleton>& trees, const GroundBox& core,
                          const GroundBox& buffered, const GroundBox& data, double margin) {
  CoreTrees out;
  // Edges that cut the data: the buffered box's side lies inside the points' bounds.
  const bool cut_x0 = buffered.x0 > data.x0, cut_x1 = buffered.x1 < data.x1;
  const bool cut_y0 = buffered.y0 > data.y0, cut_y1 = buffered.y1 < data.y1;
  for (const Skeleton& t : trees) {
    const std::vector<std::uint32_t> roots = t.roots();
    if (roots.empty()) continue;
    const Vec3 base = t.nodes[roots.front()].position;
    if (!core.contains(base.x, base.y)) continue;
    const bool touches = std::any_of(t.nodes.begin(), t.nodes.end(), [&](const SkeletonNode& n) {
      const Vec3& p = n.position;
      return (cut_x0 && p.x < buffered.x0 + margin) || (cut_x1 && p.x > buffered.x1 - margin) ||
             (cut_y0 && p.y < buffered.y0 + margin) || (cut_y1 && p.y > buffered.y1 - margin);
    });
    if (touches) out.touching.push_back(out.kept.size());
    out.kept.push_back(t);
  }
  return out;
}

}  // namespace ramus::forest
