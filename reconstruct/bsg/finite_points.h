// The points of a scan as both reconstruction methods (the BSG pipeline and the flood fill) take
// them: in double precision, with the non-finite ones marked and reported.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/point_cloud.h"
#include "reconstruct/reconstruct.h"

namespace ramus::bsg {

struct FinitePoints {
  std::vector<Eigen::Vector3d> pts;  // every point of the cloud (relative to its offset)
  std::vector<std::uint8_t> keep;    // 1 where the coordinates are finite and not an outlier
  std::size_t count = 0;             // finite points
  Eigen::Vector3d lo, hi;            // bounds of the finite points
  // All finite points at one place (within 1e-6 of their magnitude): no tree to find.
  bool coincide() const;
};

// Starts `res` for `cloud` (its input count, no tree for any point), reads the points and notes
// how many were dropped for non-finite coordinates, and how many as gross outliers (far outside
// the box of the 1st-99th percentiles; counts.outlier_points). Throws ReconstructError for an empty
// cloud or one with fewer than two finite points.
FinitePoints read_finite_points(const PointCloud& cloud, ReconstructResult& res);

}  // namespace ramus::bsg
