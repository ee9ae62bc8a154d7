// Shape measures of one tree that the branch statistics miss (docs/shape-measures.md): whether
// it is one piece, whether its segments are locked to the coordinate axes (a sign of a grammar
// that turns by right angles), its height and its trunk lean.
#pragma once

#include <cstddef>

#include "core/point_cloud.h"
#include "core/skeleton.h"

namespace ramus::shape {

// A segment within this angle of the x, y or z axis counts as axis-locked.
inline constexpr double kAxisLockDegrees = 3.0;

struct TreeShape {
  std::size_t pieces = 0;          // connected pieces with length (pieces.h)
  double largest_piece_share = 0;  // length of the longest piece / total length (0 if none)
  double axis_locked_share = 0;    // length within 3 degrees of an axis / total length
  double height = 0;               // max z - min z of the segment endpoints
  double lean_degrees = 0;         // trunk_lean.h, from samples every height / 128; NaN if
                                   // undefined
  double total_length = 0;
  std::size_t segments = 0;  // segments of positive length
};

TreeShape measure_tree_shape(const Skeleton& skeleton);

// The trunk lean of a scan (trunk_lean.h, from its points); NaN when undefined.
double lean_degrees(const PointCloud& scan);
// The trunk lean of a skeleton, from samples every height / 128 along its segments.
double lean_degrees(const Skeleton& skeleton);

}  // namespace ramus::shape
