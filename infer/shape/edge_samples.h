// Points along a skeleton's segments (parent -> child), the form in which the shape measures
// see a skeleton: the envelope and the trunk lean take the same measures of samples as of scan
// points, so a skeleton sampled densely on a tree and a scan of its bark give the same numbers.
#pragma once

#include <cstddef>
#include <vector>

#include "core/skeleton.h"
#include "core/vec3.h"

namespace ramus::shape {

// Lowest and highest z of the skeleton's segment endpoints (a sample's z lies between its
// segment's endpoints, so these are the samples' bounds too). False when it has no segment.
bool segment_z_range(const Skeleton& skeleton, double& z_min, double& z_max);

// Samples every `step` along every segment: a segment of length L gets ceil(L / step) equal
// intervals and contributes their far ends (the child end included), and every root that
// starts a segment contributes its own position once. So each node on an edge is one sample,
// whatever its number of children. Isolated roots (no segment) give nothing. Throws
// ShapeError when `step` is not positive or the samples would exceed `max_samples`.
std::vector<Vec3> sample_edges(const Skeleton& skeleton, double step,
                               std::size_t max_samples = 200'000'000);

}  // namespace ramus::shape
