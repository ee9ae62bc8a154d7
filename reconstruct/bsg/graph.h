// Building the neighbourhood graph of 4.1: voxel merging, k nearest neighbours weighted by
// squared distance, connected components (bridge.h joins them).
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "reconstruct/bsg/bsg.h"

namespace ramus::bsg {

// Merges the points (only those with keep[i] != 0) on a grid of edge `voxel`: one vertex per
// occupied voxel at the centroid of its points. point_vertex[i] is the vertex of point i (kNone
// for points not kept). Vertices are ordered by voxel key, so the result is deterministic.
Graph voxelize(const std::vector<Eigen::Vector3d>& points, const std::vector<std::uint8_t>& keep,
               double voxel, std::vector<std::uint32_t>& point_vertex);

class PointIndex;

// Links every vertex to its k nearest neighbours (symmetrically), weight = squared distance.
// `index` is a PointIndex over graph.pos, for callers that search the same vertices again.
void link_nearest(Graph& graph, int k);
void link_nearest(Graph& graph, int k, const PointIndex& index);

// Moves every vertex to the mean of itself and its graph neighbours, `steps` times. On samples of
// a branch's bark this draws them towards the branch axis, so that Dijkstra's tree follows the
// branch with one chain instead of several parallel ones along its surface.
void contract(Graph& graph, int steps);

// Connected component of every vertex (labels 0..n-1 in order of first vertex).
std::vector<std::uint32_t> components(const Graph& graph, std::uint32_t* count = nullptr);

}  // namespace ramus::bsg
