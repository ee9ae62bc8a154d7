// Where a tree stands: the base both the envelope and the trunk lean measure from. The same
// rule for scan points and for skeleton samples, so that the two are compared in one frame.
#pragma once

#include <vector>

#include "core/point_cloud.h"
#include "core/vec3.h"

namespace ramus::shape {

// Share of the height whose points make the base ("the lowest 5 %").
inline constexpr double kBaseShare = 0.05;

struct TreeBase {
  Vec3 axis;          // x, y: mean of the lowest 5 % of the height; z: the lowest z
  Vec3 low_centroid;  // mean (x, y and z) of those points
  double height = 0;  // max z - min z
};

// The base of a non-empty set of points. Throws ShapeError when it is empty.
TreeBase find_base(const std::vector<Vec3>& points);

// The cloud's points relative to its offset, in double precision: every measure here is
// translation-invariant, and the offset can be UTM-scale.
std::vector<Vec3> cloud_points(const PointCloud& cloud);

}  // namespace ramus::shape
