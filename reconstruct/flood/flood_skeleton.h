// Voxel flood-fill skeleton extraction (thesis draft section 4.2, Alg. 2-5): a fast alternative
// to the BSG reconstruction of reconstruct/reconstruct.h.
//
//   Alg. 2  voxelization of the cloud (cubic voxels, d cells along the largest extent);
//   Alg. 3  from the current node, flood the 26 neighbours layer by layer, consuming every voxel
//           it reaches, until the ratio of new voxels to the neighbourhood drops below lambda;
//   Alg. 4  the last flood layer splits into connected groups, one per child direction; sparse
//           directions are dropped and each remaining one is fitted by least squares (Eq. 4.8-4.10)
//           with a line through the current node (the child's direction and radius); the child
//           node lies at the centre of the direction's last layer;
//   Alg. 5  the child's radius is twice the mean distance of its points to the fitted line.
// Children are grown in breadth-first order, all trees of a scan in one queue, so neighbouring
// trees share the voxels between them fairly. Tree bases come from the base finder of the BSG
// pipeline (Livny et al. 4.1), which also removes the terrain. docs/flood-fill.md describes it.
#pragma once

#include <cstdint>

#include "core/point_cloud.h"
#include "reconstruct/reconstruct.h"

namespace ramus::flood {

struct FloodOptions {
  // Alg. 2: voxels along the largest extent of the cloud (the d of the pseudocode). The voxel edge
  // is also kept at least 2 median point spacings, so the non-empty voxels of a branch touch.
  int dimension = 256;
  double voxel_size = 0;  // when > 0, overrides `dimension`
  // Alg. 3: the flood of a node stops when a layer adds no more than lambda x the voxels it holds.
  double growth_ratio = 0.3;
  int max_layers = 64;  // bound on one node's flood (a thick, fully connected blob)
  // Alg. 4: voxels of the last layer at most this many cells apart belong to one direction
  // (1: 26-connected; more bridges the gaps of hollow, bark-only scans).
  int frontier_link = 2;
  // Alg. 4: directions holding fewer than this fraction of the neighbourhood's points, or fewer
  // than min_direction_points points, make no child (no thin stray twigs at every node); their
  // flood continues from the same node and becomes a branch only when it grows longer.
  double min_direction_fraction = 0.05;
  int min_direction_points = 3;
  // A last flood layer with fewer voxels than this fraction of the seed's is the corner of a
  // branch's end: the branch ends with one segment to its farthest point.
  double end_fraction = 0.25;
  // The last segment of a branch is kept when longer than this many voxel edges.
  double min_tip_voxels = 2.0;
  // Alg. 5: radius = radius_factor x mean point-to-line distance (the thesis: 2, for a solid
  // cloud; on bark-only scans the mean distance is about the radius itself).
  double radius_factor = 2.0;
  // Groups of voxels no flood reached (scan gaps) join the nearest node within this distance as
  // side branches; 0: 8% of the cloud's height, at least 3 voxels (as the BSG method).
  double max_gap = 0;
  // A group at least 10 point spacings across may join from up to this many times max_gap, in a
  // round after no other group could join: a limb that leaves its stem on the side away from the
  // scanner is seen only from where it clears the stem (as ReconstructOptions::hidden_limb_reach;
  // 1 or less: off).
  double hidden_limb_reach = 3;
  // Centre lines: nodes moved onto circles fitted to their cross-sections, radii from the fits
  // (reconstruct/bsg/centre_line.h; docs/reconstruction.md).
  bool centre_lines = true;
  // Points with fewer than two others within four point spacings (at least 1/1000 of the height)
  // are ignored before the bases, and with `stray_cluster` > 1 those of clusters of fewer points
  // linked by such steps after the terrain, as in ReconstructOptions::remove_stray.
  bool remove_stray = true;
  std::size_t stray_cluster = 1;
  // Tree bases: as in ReconstructOptions; `roots` (world positions) skips base detection.
  bool remove_terrain = true;
  std::vector<Vec3> roots;
};

// Builds one Skeleton per tree base. Throws ReconstructError for a cloud without two finite
// points; a cloud without any tree gives no trees and a note saying why. Deterministic.
// Fills timings.bases (base finding), timings.graph (voxelization), timings.forest (flood and
// fitting), timings.inflate (centre lines) and timings.total.
ReconstructResult flood_reconstruct(const PointCloud& cloud, const FloodOptions& options = {});

}  // namespace ramus::flood
