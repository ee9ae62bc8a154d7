// Refining BSGs (Livny et al. 2010, section 4.2): importance weights, the smooth orientation
// field, the smoothed embedding, and the reweighting of the graph for the next Dijkstra round.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "reconstruct/bsg/bsg.h"

namespace ramus::bsg {

// c_v = sum of edge lengths in the subtree of v, plus `own` per vertex so that leaves keep a
// positive weight; normalized so the root's weight is 1 (the solvers see weights in [0, 1]).
void importance_weights(Bsg& bsg, double own);

// The orientation field o_v minimizing Eq. 1 + Eq. 2 (one sparse LDLT solve, three columns).
std::vector<Eigen::Vector3d> orientation_field(const Bsg& bsg);

// New positions v' minimizing Eq. 3 + Eq. 4 given the orientation field.
std::vector<Eigen::Vector3d> smoothed_positions(const Bsg& bsg,
                                                const std::vector<Eigen::Vector3d>& orient);

// Weights, orientation field and positions in one call; updates bsg.pos in place.
void refine(Bsg& bsg, double own);

// Iterated BSG construction: for every edge of the refined BSG, the graph edge between the
// vertices closest to its ends is scaled by (1 - strength * |cos|) of the angle between them,
// so that Dijkstra prefers edges aligned with the refined branches. `base` holds the unscaled
// graph; the scaling is applied to a fresh copy each round, never compounded. `base_index`
// is a PointIndex over base.pos, built once for all rounds.
class PointIndex;
Graph reweighted(const Graph& base, const PointIndex& base_index, const std::vector<Bsg>& refined,
                 double strength, double max_new_edge);

}  // namespace ramus::bsg
