// Aligning a scan before quantization (Friedman & Stamos 2013, III-A).
//
// "The z-axis is the known vertical direction. The root is determined to be the point with the
// lowest z value. We then rotate the points, so that the y-axis is the projection of the vector
// from the scanner to the root, on the plane perpendicular to the z-axis passing through the
// root." The aligned frame therefore has its origin at the root, z up, +y pointing horizontally
// away from the scanner (so y is depth as seen by the scanner) and x the horizontal span of the
// most complete view.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/point_cloud.h"
#include "core/vec3.h"

namespace ramus::wavelet {

// Where the scanner direction came from.
enum class ScannerSource {
  given,     // AlignOptions::scanner
  cloud,     // PointCloud::scanner (from the file)
  centroid,  // guessed: the scanner is assumed to lie beyond the cloud's centroid
  none,      // no usable direction: identity rotation
};

struct AlignOptions {
  std::optional<Vec3> scanner;  // world coordinates; overrides the cloud's own
};

// A rigid transform world -> aligned frame: p' = Rz(angle) * (p - root).
struct Alignment {
  Vec3 root;                  // world position of the lowest point
  double angle = 0.0;         // rotation about z, radians
  Vec3 scanner_dir{0, 1, 0};  // horizontal unit direction scanner -> root, world frame
  ScannerSource source = ScannerSource::none;
  std::string warning;  // non-empty when the direction was guessed; for the caller to show

  Vec3 to_aligned(const Vec3& world) const;
  Vec3 to_world(const Vec3& aligned) const;
};

struct AlignedCloud {
  Alignment alignment;
  std::vector<Vec3> points;  // aligned frame, double precision; root at the origin
};

// Computes the alignment of III-A and applies it. Throws std::invalid_argument for an empty
// cloud or a non-finite position (the message gives the point's index).
AlignedCloud align_cloud(const PointCloud& cloud, const AlignOptions& options = {});

}  // namespace ramus::wavelet
