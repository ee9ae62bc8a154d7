// Euclidean minimum spanning tree without the complete graph.
//
// The paper (III-E, IV-E) runs Prim's algorithm on the complete graph of the significant voxels of
// a dyad and names it the bottleneck ("about 30 seconds on grids of size 128^3"). Here it is
// Boruvka's algorithm with a kd-tree (nanoflann): each round finds, for every component, its
// shortest edge to another component by nearest-neighbour queries that skip the query's own
// component, bounded by the best edge the component has so far. A point's answer stays valid
// across rounds while its neighbour is still in another component (the outside set only
// shrinks), so most points are queried once or twice. Edges are compared by (length, smaller
// index, larger index): a strict total order, so the tree is unique and the merges never close a
// cycle even on lattice points with many equal distances.
#pragma once

#include <cstdint>
#include <vector>

#include "core/vec3.h"

namespace ramus::wavelet {

struct MstEdge {
  std::uint32_t a = 0, b = 0;  // a < b
  double length = 0.0;
};

// The n - 1 edges of the EMST of `points` (none for fewer than 2 points). Throws
// std::invalid_argument for non-finite coordinates.
std::vector<MstEdge> euclidean_mst(const std::vector<Vec3>& points);

double total_length(const std::vector<MstEdge>& edges);

}  // namespace ramus::wavelet
