// Thickness-adaptive contraction of bark samples onto branch axes, before the Dijkstra forest of
// Livny et al. 2010, 4.1 (a deviation from the paper: see docs/reconstruction.md, Deviations).
//
// Every vertex is projected onto the principal line of the samples in a ball around it. The ball
// grows (doubling, on coarser and coarser voxel grids of the samples) until its samples are
// linear -- the largest eigenvalue of their covariance dominates the second -- which happens once
// the ball is a few times wider than the branch it sits on: a bark patch of a thick limb is
// planar, a ball around a 1 cm twig is linear at once. So the reach of the contraction follows
// the local branch thickness, and thick limbs and thin twigs both end up on their axes.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "reconstruct/bsg/bsg.h"

namespace ramus::bsg {

struct AxisProjectionParams {
  int levels = 4;           // grids of 2, 4, 8, 16 voxels
  double ball = 2.5;        // ball radius in cells of the level it is taken on
  int neighbours = 24;      // the ball: at most this many nearest cells within that radius
  double linearity = 4.0;   // linear when lambda_1 >= linearity * lambda_2
  int passes = 2;           // fits per cell: later ones start from the projected centroid
  double min_weight = 6.0;  // points a ball needs to be judged at all
};

// Moves graph.pos in place (the samples: graph.pos as it is on entry, weighted by graph.points).
// Each vertex goes onto the line of the finest level whose ball around the vertex's cell is
// linear; vertices linear at no level stay where they are. Returns the number moved.
// Deterministic (cells in grid-key order, fixed-size nearest-neighbour balls).
std::size_t project_to_axes(Graph& graph, double voxel, const AxisProjectionParams& params);

}  // namespace ramus::bsg
