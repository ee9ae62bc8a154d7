// The distance of the samples to a BSG's edges, d_avg of Livny et al. 2010, Eq. 7 (4.3), kept
// from call to call: the inflation measures it after every round of collapses, and a round
// after the first two changes a few edges of hundreds.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <map>
#include <utility>
#include <vector>

#include "reconstruct/bsg/bsg.h"

namespace ramus::bsg {

class SampleDistances {
 public:
  // `samples` is kept by reference: it must outlive the object.
  // `edge_sample`: the spacing of the points laid along every edge to find the edges near a
  // sample (at most 1000 points an edge). It sets only the time, not the result.
  SampleDistances(const std::vector<Eigen::Vector3d>& samples, double edge_sample);

  // The mean over the samples (weighted by `counts`, one per sample) of the distance from each
  // to the nearest edge parent -> child of `bsg` (point_segment_distance): exact, whatever the
  // edge sampling. 0 when the BSG has no edge or there are no samples. A sample whose nearest
  // edge of the last call is still an edge (same end positions) is searched only among the
  // edges that are new since; the others are searched among all.
  double mean(const Bsg& bsg, const std::vector<std::uint32_t>& counts);

 private:
  using Key = std::array<double, 6>;  // an edge's end positions, parent's first

  const std::vector<Eigen::Vector3d>& samples_;
  double edge_sample_;
  std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>> ends_;  // every edge met, by slot
  std::map<Key, std::uint32_t> slot_;
  std::vector<Eigen::Vector3d> along_;   // points laid along the edges, slot by slot
  std::vector<std::uint32_t> along_of_;  // the slot of each
  double reach_ = 0;  // no point of an edge is farther than this from its nearest along point
  std::vector<double> best_;            // per sample: the distance to its nearest edge
  std::vector<std::uint32_t> nearest_;  // and that edge's slot (kNone: to search among all)
};

}  // namespace ramus::bsg
