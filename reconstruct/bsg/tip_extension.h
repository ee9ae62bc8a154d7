// Branch tips carried out to the last wood the scan saw ahead of them.
//
// Every stage before this one pulls a tip back from the end of its branch: the voxel vertex of
// the last points is their centroid, the contraction moves an end vertex towards its only
// neighbour, and the edge removal of Livny et al. (4.3) merges the last edge into its parent at
// the weighted midpoint. On a thin twig (two or three voxels across) each of these is a voxel
// or two, and together they left the last 5-10 cm of the conifer's twigs without a skeleton.
// TreeQSM's cylinders run to the end of their last cover set, AdTree's skeleton to its last
// point; here a tip walks on along its branch while unclaimed samples lie ahead of it.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "reconstruct/bsg/bsg.h"
#include "reconstruct/bsg/kdtree.h"

namespace ramus::bsg {

struct TipExtensionParams {
  double spacing = 0.01;     // the voxel: step, search radius and claim distance scale with it
  double reach = 3.0;        // samples are looked for within this many voxels of the tip
  double cone = 0.6;         // ... and at most this x their distance ahead off the branch line
  double max_length = 30.0;  // a tip moves at most this many voxels in all
  double direction_back =
      3.0;  // the branch direction is taken over this many voxels behind the tip
};

// Walks every tip of `b` (a node without children) on along its branch while samples lie ahead
// of it that no other edge of `b` claims (within max(its radius, spacing) of it), and moves the
// tip to where the walk ended. Returns the number of tips moved.
std::size_t extend_tips(Bsg& b, const std::vector<Eigen::Vector3d>& samples,
                        const PointIndex& index, const TipExtensionParams& params);

}  // namespace ramus::bsg
