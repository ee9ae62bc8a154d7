// Symmetrization of a single-view scan (Friedman & Stamos 2013, IV-D).
//
// "Each range scan presents only a single view of a tree. The sampling of points is biased
// towards those facing the scanner. Symmetrizing the tree, by reflecting about the plane
// perpendicular to the scanner and centered at the tree root, mitigates this bias." The plane is
// vertical (z is up, III-A), passes through the root r and has as its normal the horizontal
// direction n from the scanner s to the root: in the aligned frame of III-A it is the plane y = 0
// and the reflection is y -> -y. In world coordinates p' = p - 2 ((p - r) . n) n.
//
// The paper uses the merged cloud (original + reflection) as a preprocessing step before
// quantization, which avoids the rigid mirror symmetry of the reflected points themselves
// (its Figures 15-18).
#pragma once

#include <cstddef>

#include "core/point_cloud.h"
#include "core/vec3.h"
#include "infer/wavelet/alignment.h"

namespace ramus::wavelet {

// The mirror image of the world point `p` in the plane through `a.root` whose normal is
// `a.scanner_dir` (horizontal, unit). An involution; points of the plane are fixed.
Vec3 reflect_about_scanner_plane(const Alignment& a, const Vec3& p);

struct SymmetrizeOptions {
  // A reflected point closer than this (world units) to a point of the input is dropped, so
  // that points on the plane and an input that is already symmetric are not doubled. Negative:
  // 1e-6 of the cloud's bounding-box diagonal (float rounding of the stored positions).
  double merge_distance = -1;
};

struct Symmetrized {
  PointCloud cloud;           // the input's points first (in order), then the kept reflections
  std::size_t reflected = 0;  // reflections added
  std::size_t merged = 0;     // reflections dropped as duplicates of input points
  double merge_distance = 0;  // the distance used
};

// The input merged with its reflection about the scanner plane of `a` (the alignment of the
// same cloud). Normals are reflected too; intensity and classification are copied. The offset,
// the scanner and the source are kept, so the merged cloud aligns exactly as the input did
// (the root lies on the plane and stays the lowest point).
Symmetrized symmetrize(const PointCloud& cloud, const Alignment& a,
                       const SymmetrizeOptions& options = {});

}  // namespace ramus::wavelet
