#include "infer/wavelet/alignment.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace ramus::wavelet {
namespace {

// Horizontal distance below which a scanner is treated as straight above/below the root.
constexpr double kMinHorizontal = 1e-9;

Vec3 rotate_z(const Vec3& p, double angle) {
  double c = std::cos(angle), s = std::sin(angle);
  return {c * p.x - s * p.y, s * p.x + c * p.y, p.z};
}

std::size_t lowest_point(const PointCloud& cloud) {
  std::size_t best = 0;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const Vec3f& p = cloud.positions[i];
    if (!is_finite(p)) {
      throw std::invalid_argument("point " + std::to_string(i) + " has a non-finite coordinate");
    }
    // Ties go to the first point, so the result does not depend on anything but the order.
    if (p.z < cloud.positions[best].z) best = i;
  }
  return best;
}

Vec3 centroid(const PointCloud& cloud) {
  Vec3 sum;
  for (const Vec3f& p : cloud.positions) sum += Vec3(p);
  return cloud.offset + sum / double(cloud.size());
}

// The horizontal unit vector from `from` to `to`, if it is long enough to define a direction.
std::optional<Vec3> horizontal_dir(const Vec3& from, const Vec3& to) {
  Vec3 d{to.x - from.x, to.y - from.y, 0.0};
  double len = length(d);
  if (!(len > kMinHorizontal) || !std::isfinite(len)) return std::nullopt;
  return d / len;
}

}  // namespace

Vec3 Alignment::to_aligned(const Vec3& world) const { return rotate_z(world - root, angle); }
Vec3 Alignment::to_world(const Vec3& aligned) const { return rotate_z(aligned, -angle) + root; }

AlignedCloud align_cloud(const PointCloud& cloud, const AlignOptions& options) {
  if (cloud.empty()) throw std::invalid_argument("the point cloud is empty");
  AlignedCloud out;
  Alignment& a = out.alignment;
  a.root = cloud.world(lowest_point(cloud));

  std::optional<Vec3> dir;
  if (options.scanner) {
    dir = horizontal_dir(*options.scanner, a.root);
    a.source = ScannerSource::given;
  } else if (cloud.scanner) {
    dir = horizontal_dir(*cloud.scanner, a.root);
    a.source = ScannerSource::cloud;
  }
  if (a.source != ScannerSource::none && !dir) {
    a.warning = "the scanner is straight above or below the root; using the centroid direction";
  }
  if (!dir) {
    // A single view samples the side facing the scanner more densely, so the centroid lies
    // between the root and the scanner: centroid -> root approximates scanner -> root.
    dir = horizontal_dir(centroid(cloud), a.root);
    a.source = ScannerSource::centroid;
    if (a.warning.empty()) {
      a.warning = "no scanner position; assuming the scanner lies beyond the cloud's centroid";
    }
  }
  if (!dir) {
    a.source = ScannerSource::none;
    a.warning = "no scanner position and the centroid is above the root; axes left unrotated";
    dir = Vec3{0, 1, 0};
  }
  a.scanner_dir = *dir;
  // Rotate so that `dir` becomes +y: the angle from dir to +y about z.
  a.angle = std::atan2(dir->x, dir->y);

  out.points.reserve(cloud.size());
  for (std::size_t i = 0; i < cloud.size(); ++i) out.points.push_back(a.to_aligned(cloud.world(i)));
  return out;
}

}  // namespace ramus::wavelet
