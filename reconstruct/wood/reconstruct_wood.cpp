#include "reconstruct/wood/reconstruct_wood.h"

#include <chrono>
#include <cstdio>

namespace ramus {

namespace {

std::string percent(double f) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f%%", 100 * f);
  return buf;
}

}  // namespace

ReconstructResult reconstruct_without_leaves(const PointCloud& cloud,
                                             const ReconstructOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  ReconstructOptions inner = options;
  inner.leaves_in_scan = LeafHandling::kKeep;
  // reconstruct() names what is wrong with a cloud that has no usable point.
  if (cloud.empty()) return reconstruct(cloud, inner);
  const WoodSeparation ws = separate_wood(cloud);
  std::string note;
  bool remove = options.leaves_in_scan == LeafHandling::kRemove;
  if (options.leaves_in_scan == LeafHandling::kAuto) {
    remove = ws.leaf_fraction >= WoodOptions{}.auto_leaf_fraction;
    note = "wood/leaf separation: " + percent(ws.leaf_fraction) + " of the points look like " +
           (remove ? "foliage: removed" : "foliage, too few to remove: all points kept");
  } else {
    note =
        "wood/leaf separation: " + percent(ws.leaf_fraction) + " of the points removed as foliage";
  }
  if (remove && ws.finite_points - ws.leaf_points < 2) {
    remove = false;
    note = "wood/leaf separation left fewer than two wood points: all points kept";
  }
  if (!remove || ws.leaf_points == 0) {
    ReconstructResult r = reconstruct(cloud, inner);
    r.notes.insert(r.notes.begin(), note);
    return r;
  }
  ReconstructResult r = reconstruct(select_points(cloud, ws.wood), inner);
  // Back to the input's indexing: leaf and non-finite points belong to no tree.
  std::vector<std::uint32_t> point_tree(cloud.size(), ReconstructResult::kNoTree);
  std::size_t k = 0;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    if (ws.wood[i]) point_tree[i] = r.point_tree[k++];
  }
  r.point_tree = std::move(point_tree);
  r.counts.dropped_points += cloud.size() - ws.finite_points;
  r.counts.input_points = cloud.size();
  r.notes.insert(r.notes.begin(), note);
  r.timings.total = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

}  // namespace ramus
