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

std::string number(const char* format, double v) {
  char buf[48];
  std::snprintf(buf, sizeof buf, format, v);
  return buf;
}

}  // namespace

LeafDecision decide_leaf_removal(const WoodSeparation& ws, LeafHandling handling,
                                 const WoodOptions& o) {
  LeafDecision d;
  const std::string evidence =
      percent(ws.leaf_fraction) + " of the points classified leaf (Ashman's D " +
      number("%.2f", ws.separation) + ", " + percent(ws.upper_share) +
      " of the cells above Otsu's threshold, spacing " + number("%.3g", ws.spacing) +
      " for a height of " + number("%.3g", ws.height) + ")";
  if (handling == LeafHandling::kRemove) {
    d.remove = true;
    d.note = "wood/leaf separation: " + evidence + ": removed";
  } else if (handling == LeafHandling::kAuto) {
    // Every test must point to foliage; any doubt keeps the scan whole, because removing the
    // twigs of a leafless crown loses the tree while keeping a few leaves only adds spurs.
    const bool resolved = ws.height > 0 && ws.spacing <= o.auto_max_spacing * ws.height;
    d.remove = ws.leaf_mode && resolved && ws.leaf_fraction >= o.auto_leaf_fraction;
    const char* why =
        d.remove        ? "foliage found: removed"
        : !ws.leaf_mode ? "no separate foliage mode: the scan is wood, all points kept"
        : !resolved     ? "the scan is too sparse to tell leaves from twigs: all points kept"
                        : "too few to be foliage: all points kept";
    d.note = "wood/leaf separation (auto): " + evidence + "; " + why;
  }
  return d;
}

ReconstructResult reconstruct_without_leaves(const PointCloud& cloud,
                                             const ReconstructOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  ReconstructOptions inner = options;
  inner.leaves_in_scan = LeafHandling::kKeep;
  // reconstruct() names what is wrong with a cloud that has no usable point.
  if (cloud.empty()) return reconstruct(cloud, inner);
  const WoodSeparation ws = separate_wood(cloud);
  const LeafDecision decision = decide_leaf_removal(ws, options.leaves_in_scan);
  std::string note = decision.note;
  bool remove = decision.remove;
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
