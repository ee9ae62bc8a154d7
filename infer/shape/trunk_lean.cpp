#include "infer/shape/trunk_lean.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "infer/shape/envelope.h"
#include "infer/shape/tree_base.h"

namespace ramus::shape {

namespace {

double median_of(std::vector<double> v) {
  const std::size_t mid = (v.size() - 1) / 2;
  std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(mid), v.end());
  return v[mid];
}

}  // namespace

double trunk_lean_degrees(const std::vector<Vec3>& points) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  if (points.empty()) return nan;
  const TreeBase base = find_base(points);
  const double h = base.height;
  if (!(h > 0)) return nan;
  const Vec3 b0 = base.low_centroid;
  const double z0 = base.axis.z;

  std::vector<double> low_r;
  for (const Vec3& p : points) {
    if (p.z <= z0 + kBaseShare * h) low_r.push_back(std::hypot(p.x - b0.x, p.y - b0.y));
  }
  const double w = std::max(h / kEnvelopeCells, 2 * median_of(low_r));

  // Points of each slice from the top of the base region to the top of the band.
  const double thick = h / kLeanSlices;
  const int first = int(std::floor(kBaseShare * kLeanSlices));
  const int last = int(std::ceil(kLeanBandHigh * kLeanSlices));
  std::vector<std::vector<Vec3>> slices(std::size_t(last - first));
  for (const Vec3& p : points) {
    const int k = int(std::floor((p.z - z0) / thick));
    if (k >= first && k < last) slices[std::size_t(k - first)].push_back(p);
  }

  Vec3 dir{0, 0, 1};  // horizontal offset per unit of height, from b0
  Vec3 sum_all, sum_band;
  double n_all = 0, n_band = 0;
  for (std::size_t k = 0; k < slices.size(); ++k) {
    const std::vector<Vec3>& slice = slices[k];
    if (slice.empty()) continue;
    const double mid_z = z0 + (double(first + int(k)) + 0.5) * thick;
    Vec3 centre = b0 + dir * (mid_z - b0.z);
    bool found = false;
    for (int shift = 0; shift < kLeanShifts; ++shift) {
      Vec3 sum;
      double n = 0;
      for (const Vec3& p : slice) {
        if (std::hypot(p.x - centre.x, p.y - centre.y) <= w) {
          sum += p;
          n += 1;
        }
      }
      if (n == 0) break;
      centre = sum / n;
      found = true;
    }
    if (!found) continue;
    sum_all += centre;
    n_all += 1;
    const Vec3 d = sum_all / n_all - b0;
    if (d.z > 0) dir = d / d.z;
    const double above = centre.z - z0;
    if (above >= kLeanBandLow * h && above <= kLeanBandHigh * h) {
      sum_band += centre;
      n_band += 1;
    }
  }
  if (n_band == 0) return nan;
  const Vec3 d = sum_band / n_band - b0;
  if (!(d.z > 0)) return nan;
  constexpr double kDegrees = 180.0 / 3.14159265358979323846;
  return std::atan2(std::hypot(d.x, d.y), d.z) * kDegrees;
}

}  // namespace ramus::shape
