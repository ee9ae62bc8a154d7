// Internal types of the reconstruction pipeline (reconstruct/reconstruct.h is the interface).
//
// The neighbourhood graph lives on voxel-merged points ("vertices"); a Forest is the result of
// the multi-root Dijkstra over it (4.1); a Bsg is one tree of that forest, re-indexed so that
// every parent comes before its children, with the per-vertex quantities of 4.2 and 4.3.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace ramus::bsg {

inline constexpr std::uint32_t kNone = 0xffffffffu;

// Distance from p to the segment a-b (to a when the segment is a point): the skeleton comparison
// and the inflation's merge check measure points against edges the same way.
inline double point_segment_distance(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                     const Eigen::Vector3d& b) {
  const Eigen::Vector3d ab = b - a;
  const double l2 = ab.squaredNorm();
  const double t = l2 > 0 ? std::clamp((p - a).dot(ab) / l2, 0.0, 1.0) : 0.0;
  return (p - a - t * ab).norm();
}

// Two unit vectors that make (e1, e2, d) an orthonormal frame around the unit direction d: the
// plane of a cross-section. Every slab, cylinder and cover pattern takes the same frame (the
// helper axis z, or x for directions within 26 degrees of it).
inline void perpendicular_frame(const Eigen::Vector3d& d, Eigen::Vector3d& e1,
                                Eigen::Vector3d& e2) {
  const Eigen::Vector3d helper =
      std::abs(d.z()) < 0.9 ? Eigen::Vector3d::UnitZ() : Eigen::Vector3d::UnitX();
  e1 = d.cross(helper).normalized();
  e2 = d.cross(e1);
}

struct Arc {
  std::uint32_t to;
  double weight;  // squared Euclidean length, scaled by the reweighting of 4.2
};

// Voxel-merged points and the neighbourhood graph between them. Positions are relative to the
// cloud's offset, in double precision for the solvers.
struct Graph {
  std::vector<Eigen::Vector3d> pos;
  std::vector<std::uint32_t> points;  // input points merged into each vertex
  std::vector<std::vector<Arc>> adj;  // symmetric
  std::size_t size() const { return pos.size(); }
  std::size_t edge_count() const;
  // Adds u-v in both directions unless present; returns whether it was added.
  bool add_edge(std::uint32_t u, std::uint32_t v, double weight);
  // Multiplies the weight of u-v (both directions) by `factor`; returns false if absent.
  bool scale_edge(std::uint32_t u, std::uint32_t v, double factor);
};

// Shortest-path forest from all roots at once.
struct Forest {
  std::vector<std::uint32_t> parent;  // kNone for roots and unreached vertices
  std::vector<std::uint32_t> tree;    // index of the root's tree, kNone if unreached
  std::vector<std::uint32_t> order;   // reached vertices in the order Dijkstra settled them
};

// One Branch-Structure Graph. Index 0 is the root; parent[i] < i for every other vertex.
struct Bsg {
  std::vector<Eigen::Vector3d> pos;
  std::vector<std::uint32_t> parent;
  std::vector<std::uint32_t> vertex;  // graph vertex it started from (kNone once merged)
  std::vector<double> weight;         // importance c_v (4.2), normalized so the root's is 1
  std::vector<double> radius;         // r_v (4.3)
  std::vector<double> mass;           // input points represented (grows as edges collapse)
  std::size_t size() const { return pos.size(); }
};

// Children lists of a parent array (parents before children).
std::vector<std::vector<std::uint32_t>> children_of(const std::vector<std::uint32_t>& parent);

// Appends node v of `from` (every field) to `to` with the parent index `parent` of `to`.
void append_node(Bsg& to, const Bsg& from, std::uint32_t v, std::uint32_t parent);

// The nodes of `b` again in parent-first order: a depth-first walk from the root 0 visiting the
// children of each node in the order of `children`. old_of, when given, receives the old index
// of every new node.
Bsg depth_first(const Bsg& b, const std::vector<std::vector<std::uint32_t>>& children,
                std::vector<std::uint32_t>* old_of = nullptr);

}  // namespace ramus::bsg
