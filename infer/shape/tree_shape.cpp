#include "infer/shape/tree_shape.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "infer/shape/edge_samples.h"
#include "infer/shape/envelope.h"
#include "infer/shape/pieces.h"
#include "infer/shape/tree_base.h"
#include "infer/shape/trunk_lean.h"

namespace ramus::shape {

namespace {

// Length of the segments whose direction lies within kAxisLockDegrees of a coordinate axis.
double axis_locked_length(const Skeleton& s) {
  const double cos_lock = std::cos(kAxisLockDegrees * 3.14159265358979323846 / 180.0);
  double locked = 0;
  for (const SkeletonNode& node : s.nodes) {
    if (node.parent == kNoParent) continue;
    const Vec3 d = node.position - s.nodes[node.parent].position;
    const double l = length(d);
    if (!(l > 0)) continue;
    const double along = std::max({std::abs(d.x), std::abs(d.y), std::abs(d.z)});
    if (along >= cos_lock * l) locked += l;
  }
  return locked;
}

}  // namespace

double lean_degrees(const PointCloud& scan) { return trunk_lean_degrees(cloud_points(scan)); }

double lean_degrees(const Skeleton& skeleton) {
  double lo = 0, hi = 0;
  if (!segment_z_range(skeleton, lo, hi) || !(hi > lo)) {
    return std::numeric_limits<double>::quiet_NaN();
  }
  // The envelope's sampling of a reference: a quarter of its cell. The trunk's foot is the
  // lowest root that has a segment.
  const std::vector<Vec3> samples =
      sample_edges(skeleton, (hi - lo) / (kEnvelopeCells * kSamplesPerCell));
  const Skeleton::Children children = skeleton.children();
  const Vec3* foot = nullptr;
  for (std::uint32_t r : skeleton.roots()) {
    if (children.count(r) == 0) continue;
    const Vec3& p = skeleton.nodes[r].position;
    if (foot == nullptr || p.z < foot->z) foot = &p;
  }
  return foot ? trunk_lean_degrees(samples, *foot) : trunk_lean_degrees(samples);
}

TreeShape measure_tree_shape(const Skeleton& skeleton) {
  TreeShape t;
  const Pieces p = find_pieces(skeleton);
  t.pieces = p.count;
  t.total_length = p.total_length;
  t.largest_piece_share = p.total_length > 0 ? p.largest_length / p.total_length : 0.0;
  t.axis_locked_share = p.total_length > 0 ? axis_locked_length(skeleton) / p.total_length : 0.0;
  double lo = 0, hi = 0;
  if (segment_z_range(skeleton, lo, hi)) t.height = hi - lo;
  for (const SkeletonNode& node : skeleton.nodes) {
    if (node.parent != kNoParent &&
        distance(node.position, skeleton.nodes[node.parent].position) > 0) {
      ++t.segments;
    }
  }
  t.lean_degrees = lean_degrees(skeleton);
  return t;
}

}  // namespace ramus::shape
