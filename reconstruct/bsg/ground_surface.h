// Which points of the lowest layer are ground (4.1's terrain removal).
//
// The terrain layer is every point within a band above the ground envelope, and the envelope is
// the lowest point of each coarse cell. Where the scan has no ground under a cell (a single tree
// cut out of its plot, the simulated scans, the bundled scans) the lowest point of that cell is a
// branch, and the band took the drooping branch ends of a conifer's lowest whorls with it (the
// conifer's recall from three stations 0.885; 0.928 with this) and low branches of the bundled
// scans. Ground is a surface: near-horizontal and flat wherever one looks at it closely, and
// joined over a wide area. A branch is a line, and a flat spray of twigs is flat only around its
// forks, in patches a fraction of the tree's height across.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

namespace ramus::bsg {

struct GroundSurfaceParams {
  int neighbours = 16;         // k of the neighbourhoods whose shape is measured
  double min_spread = 0.2;     // flat: second eigenvalue at least this x the first ...
  double min_normal_z = 0.8;   // ... and the normal within 37 degrees of the vertical
  double join_spacings = 3.0;  // flat neighbours join within this x the larger local spacing
  double min_extent = 1.0;     // a surface at least this wide (x or y) is ground
};

// Per point of `pts`: 1 when it is ground. A point is ground when it is flat and its surface is
// min_extent wide or more, or when most of its neighbours are (clutter on the ground: grass,
// stones, a noisy return). Fewer points than `neighbours` + 1 are no ground.
std::vector<std::uint8_t> ground_surface(const std::vector<Eigen::Vector3d>& pts,
                                         const GroundSurfaceParams& params);

}  // namespace ramus::bsg
