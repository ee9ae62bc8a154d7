// Trunk lean: how far from vertical a tree's trunk stands, taken the same way from scan points
// and from skeleton samples (docs/shape-measures.md).
//
// The trunk is followed upwards from b0, the centroid of the lowest 5 % of the height (H), in
// slices H / 64 thick up to 0.3 H: in each slice, the centre is the mean of the points within a
// trunk radius w (horizontally) of where the line fitted so far (least squares of x and y
// against z through b0 and the earlier centres) predicts it, re-centred three times (mean
// shift). The lean is the angle from vertical of the vector from b0 to the mean of the centres
// of the slices whose height above the lowest point lies in [0.1 H, 0.3 H].
// w = max(H / 32, twice the median horizontal distance of the lowest 5 % from b0): a skeleton's
// trunk is a line, a scan's a ring of bark. Points farther than w from the trunk never count,
// so side branches and drooping twigs cannot tip it; a mean over the whole band kept below its
// median distance (the first version) gave 38 degrees for the vertical trunk of the bundled
// broadleaf, whose drooping twigs hold more of the band's samples than its trunk does.
#pragma once

#include <optional>
#include <vector>

#include "core/vec3.h"

namespace ramus::shape {

inline constexpr double kLeanBandLow = 0.1;   // share of the height where the band starts
inline constexpr double kLeanBandHigh = 0.3;  // and where it ends
inline constexpr int kLeanSlices = 64;        // slice thickness: height / 64
inline constexpr int kLeanShifts = 3;         // mean-shift steps per slice

// The centre of a slab of a trunk: starting at `start`, moved `shifts` times to the mean of the
// points within `window` of it horizontally (mean shift); nothing when no point is that close.
// The trunk lean tracks a trunk with it, and so does wavelet inference (tree_hierarchy.cpp).
std::optional<Vec3> trunk_centre(const std::vector<Vec3>& slab, Vec3 start, double window,
                                 int shifts = kLeanShifts);

// The lean in degrees in [0, 90); NaN when it is undefined (no height, no trunk found in the
// band).
double trunk_lean_degrees(const std::vector<Vec3>& points);

// The same from a known foot of the trunk (a skeleton's root): b0 is the foot, heights are
// measured from it, points below it are left out (the whips of a weeping tree hang below its
// root and put the centroid of the lowest 5 % among them: 33 degrees for a vertical trunk), and
// the window is the envelope's cell, height / 32.
double trunk_lean_degrees(const std::vector<Vec3>& points, const Vec3& foot);

}  // namespace ramus::shape
