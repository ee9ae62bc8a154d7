// The trunk followed up the wood with cylinders, and the skeleton hung from it. On a one-sided
// scan of a conifer the BSG's shortest paths (Livny et al. 2010, 4.1) do not climb the trunk:
// below each whorl its front is hidden by the whorl's drooping branches, so the path leaves the
// trunk along a branch of the whorl below, crosses to a drooping branch of the whorl above and
// walks it back in (a V), and the centre lines, which keep the topology, cannot bring such a chain
// to the axis. TreeQSM grows a stem from its base segment by segment (Raumonen et al. 2013,
// Remote Sens. 5(2), section 2.3: cylinders fitted to each segment, the next one searched
// along the last one's axis); here the trunk is continued from its fitted base the same way,
// through the samples and not along the BSG's chain, and then replaces the chain it passes.
// docs/reconstruction.md, "Centre lines", step 7.
#pragma once

#include <cstdint>
#include <vector>

#include "reconstruct/bsg/bsg.h"
#include "reconstruct/bsg/kdtree.h"

namespace ramus::bsg {

struct StemTrack {
  std::vector<Eigen::Vector3d> axis;  // from the start node's position upwards
  std::vector<double> radius;
  std::vector<std::uint8_t> fitted;  // 1 where a fit (or a fitted node) placed it, 0 where extended
};

// The trunk's axis continued from the first run of fitted nodes on the root's heaviest chain
// (starting within its first quarter): cylinders of max(2 r, 6 spacings) fitted ahead along the
// chord of the accepted axis, each accepted on the centre lines' terms (arc, inliers, residual,
// axial fill) and as a continuation (radius 0.6-1.15 x the median of the last three, axis within
// 15 degrees and half a radius of the prediction), else a circle across the predicted axis on
// the same terms; where neither is accepted (a whorl, an occluded stretch) the axis goes on
// straight for at most three pieces. Fitted nodes of the run that lie off its axis (a line over
// its first ten radii, beyond them the line of the kept nodes of the last ten radii) neither
// start nor steer the track:
// it starts from the last node on the axis, with the median radius of the last five there, and
// the nodes on the axis become the track's first points, from the run's first node, which is
// then `start` (so rehang_on_track replaces the others). When the run's last two nodes or more
// are off the axis (the chain went on into a limb), the run is taken as it is; one node off it
// (a whorl branch's base) is left out like the others. When the run starts above the root
// (ground clutter, a root flare), the track also runs straight down from it to the root's level,
// along the line fitted to the base and the track's fitted points within 20 base radii, and
// `start` is the root, which rehang_on_track moves onto it; otherwise `start` is the run's last
// node. Each point's radius is the median of its own and its neighbours', and at most the radius
// below it (a trunk does not thicken upwards). Empty when the base run is shorter than two radii,
// or when nothing beyond it was accepted and no node of it was off its axis.
StemTrack track_trunk(const Bsg& b, const std::vector<std::uint8_t>& fitted,
                      const PointIndex& index, const std::vector<Eigen::Vector3d>& samples,
                      const std::vector<double>& weight, double spacing, std::uint32_t& start);

// Replaces what the track passes: the start node's descendants within 1.25 x the track's radius
// (plus two spacings) of its axis go (the chain that wandered over the bark and out along the
// whorls, the first nodes of every branch on the bark), the track's points become a chain of
// nodes from `start`, and everything that hung from a removed node hangs from the track's nearest
// node. Parents stay before children; `fitted` follows the nodes (track nodes take their piece's
// flag). Returns the nodes removed.
std::size_t rehang_on_track(Bsg& b, std::vector<std::uint8_t>& fitted, const StemTrack& track,
                            std::uint32_t start, double spacing);

}  // namespace ramus::bsg
