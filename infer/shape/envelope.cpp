#include "infer/shape/envelope.h"

#include <algorithm>
#include <cmath>
#include <iterator>

#include "infer/shape/edge_samples.h"
#include "infer/shape/shape_error.h"

namespace ramus::shape {

namespace {

// Cell indices saturate instead of wrapping, so a tree far larger than the reference still
// lands in distinct, far-away cells and never aliases onto the reference's.
std::uint64_t index_of(double v, double cell) {
  const double i = std::floor(v / cell);
  return std::uint64_t(std::clamp(i, 0.0, 4294967295.0));
}

Envelope envelope_of(const std::vector<Vec3>& points, double cell) {
  Envelope e;
  e.cell = cell;
  if (points.empty()) return e;
  e.base = find_base(points);
  e.cells.reserve(points.size());
  for (const Vec3& p : points) {
    const double r = std::hypot(p.x - e.base.axis.x, p.y - e.base.axis.y);
    e.cells.push_back(index_of(r, cell) << 32 | index_of(p.z - e.base.axis.z, cell));
  }
  std::sort(e.cells.begin(), e.cells.end());
  e.cells.erase(std::unique(e.cells.begin(), e.cells.end()), e.cells.end());
  return e;
}

}  // namespace

Envelope scan_envelope(const PointCloud& scan) {
  const std::vector<Vec3> points = cloud_points(scan);
  if (points.empty()) throw ShapeError("the scan has no points");
  const double h = find_base(points).height;
  if (!(h > 0)) throw ShapeError("the scan has no height (all points at one z)");
  return envelope_of(points, h / kEnvelopeCells);
}

Envelope reference_envelope(const Skeleton& reference) {
  double lo = 0, hi = 0;
  if (!segment_z_range(reference, lo, hi) || !(hi > lo)) {
    throw ShapeError("the reference skeleton has no height");
  }
  return skeleton_envelope(reference, (hi - lo) / kEnvelopeCells);
}

Envelope skeleton_envelope(const Skeleton& skeleton, double cell) {
  if (!(cell > 0) || !std::isfinite(cell)) throw ShapeError("the envelope cell must be positive");
  return envelope_of(sample_edges(skeleton, cell / kSamplesPerCell), cell);
}

double envelope_iou(const Envelope& a, const Envelope& b) {
  std::vector<std::uint64_t> both;
  std::set_intersection(a.cells.begin(), a.cells.end(), b.cells.begin(), b.cells.end(),
                        std::back_inserter(both));
  const std::size_t uni = a.cells.size() + b.cells.size() - both.size();
  return uni == 0 ? 0.0 : double(both.size()) / double(uni);
}

double envelope_iou(const Envelope& reference, const Skeleton& skeleton) {
  return envelope_iou(reference, skeleton_envelope(skeleton, reference.cell));
}

double envelope_iou(const PointCloud& scan, const Skeleton& skeleton) {
  return envelope_iou(scan_envelope(scan), skeleton);
}

double envelope_iou(const Skeleton& reference, const Skeleton& skeleton) {
  return envelope_iou(reference_envelope(reference), skeleton);
}

}  // namespace ramus::shape
