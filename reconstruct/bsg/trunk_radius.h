// The trunk radius at a tree's base, measured on the scan: it fixes the scale of Livny et al.'s
// radii (4.3, Eq. 7 replaced; docs/reconstruction.md, Deviations, "Trunk radius from a circle
// fit") and so the cylinders of the inflation and every radius hint of the centre lines.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace ramus::bsg {

// Robust circle fits (circle_fit.h) to the horizontal positions of the samples in thin slabs of
// [base.z, base.z + height], within max_width / 2 of the base. In each slab the search window
// shrinks (halving, re-centred on the median of the samples it held) until a circle passes the
// centre lines' acceptance (arc, inliers, residual) and lies inside the window: the first window
// around a clean trunk accepts its circle, while in a conifer's skirt of branches and ground
// points the trunk's ring is found only in a window it fills. The median of the accepted slabs'
// radii, or 0 (unknown) when fewer than two slabs accept one. `spacing` is the point spacing
// (the voxel): it floors the radius and the window and sets the noise floor of the fits.
double trunk_radius(const std::vector<Eigen::Vector3d>& samples, const Eigen::Vector3d& base,
                    double height, double max_width, double spacing);

}  // namespace ramus::bsg
