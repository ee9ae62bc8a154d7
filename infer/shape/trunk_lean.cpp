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

// x = x0 + slope_x (z - z_mean), the same for y: the least-squares line of points against
// their height (a trunk is nearer vertical than horizontal, so z is the parameter).
// All points at one height (b0 alone): vertical through their mean.
struct Line {
  Vec3 mean;
  double slope_x = 0, slope_y = 0;
  Vec3 at(double z) const {
    return {mean.x + slope_x * (z - mean.z), mean.y + slope_y * (z - mean.z), z};
  }
};

Line fit_line(const std::vector<Vec3>& points) {
  Line l;
  for (const Vec3& p : points) l.mean += p;
  l.mean = l.mean / double(points.size());
  double zz = 0, xz = 0, yz = 0;
  for (const Vec3& p : points) {
    const Vec3 d = p - l.mean;
    zz += d.z * d.z;
    xz += d.x * d.z;
    yz += d.y * d.z;
  }
  if (zz > 0) {
    l.slope_x = xz / zz;
    l.slope_y = yz / zz;
  }
  return l;
}

// The centres of the trunk in the slices whose height above the lowest point lies in the band,
// tracked from b0 upwards; `start` predicts the first centre.
std::vector<Vec3> track_trunk(const std::vector<std::vector<Vec3>>& slices, int first, double thick,
                              double z0, double h, double w, const Vec3& b0, const Line& start) {
  // Slice centres found so far, and where the trunk's line through them and b0 crosses a
  // height (least squares of x and y against z; `start` until a centre is found).
  std::vector<Vec3> centres{b0};
  auto predict = [&](double z) {
    return centres.size() > 1 ? fit_line(centres).at(z) : start.at(z);
  };
  std::vector<Vec3> band;
  for (std::size_t k = 0; k < slices.size(); ++k) {
    const std::vector<Vec3>& slice = slices[k];
    if (slice.empty()) continue;
    const std::optional<Vec3> found =
        trunk_centre(slice, predict(z0 + (double(first + int(k)) + 0.5) * thick), w);
    if (!found) continue;
    const Vec3 centre = *found;
    centres.push_back(centre);
    const double above = centre.z - z0;
    if (above >= kLeanBandLow * h && above <= kLeanBandHigh * h) band.push_back(centre);
  }
  return band;
}

// The lean of the trunk tracked from b0 through the slices of `points` above z0 (see the
// header), in a window of horizontal radius w.
double lean_from(const std::vector<Vec3>& points, const Vec3& b0, double z0, double h, double w,
                 const std::vector<Vec3>& low) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  // Points of each slice from the top of the base region to the top of the band.
  const double thick = h / kLeanSlices;
  const int first = int(std::floor(kBaseShare * kLeanSlices));
  const int last = int(std::ceil(kLeanBandHigh * kLeanSlices));
  std::vector<std::vector<Vec3>> slices(std::size_t(last - first));
  for (const Vec3& p : points) {
    const int k = int(std::floor((p.z - z0) / thick));
    if (k >= first && k < last) slices[std::size_t(k - first)].push_back(p);
  }

  // First from a vertical through b0; when that finds no trunk in the band (a trunk leaning
  // so far that it leaves the window within the first slices, as the 45-degree first internode
  // of some inferred grammars does), again along the line fitted to the lowest 5 %, which
  // follows such a trunk but is swayed by roots or low stems, hence second.
  Line vertical;
  vertical.mean = b0;
  std::vector<Vec3> band = track_trunk(slices, first, thick, z0, h, w, b0, vertical);
  if (band.empty()) band = track_trunk(slices, first, thick, z0, h, w, b0, fit_line(low));
  // From b0 to the mean of the band's centres rather than the slope of a line through them:
  // where a trunk forks inside the band, the top centres follow the fork, and a slope, whose
  // lever is half the band, turned that into 20 degrees for the reconstruction of
  // adtree_tree1 against 2 for its scan.
  if (band.empty()) return nan;
  Vec3 mean;
  for (const Vec3& c : band) mean += c;
  const Vec3 d = mean / double(band.size()) - b0;
  if (!(d.z > 0)) return nan;
  constexpr double kDegrees = 180.0 / 3.14159265358979323846;
  return std::atan2(std::hypot(d.x, d.y), d.z) * kDegrees;
}

}  // namespace

std::optional<Vec3> trunk_centre(const std::vector<Vec3>& slab, Vec3 start, double window,
                                 int shifts) {
  std::optional<Vec3> centre;
  for (int shift = 0; shift < shifts; ++shift) {
    Vec3 sum{0, 0, 0};
    double n = 0;
    for (const Vec3& p : slab) {
      if (std::hypot(p.x - start.x, p.y - start.y) > window) continue;
      sum += p;
      n += 1;
    }
    if (n == 0) break;
    start = sum / n;
    centre = start;
  }
  return centre;
}

double trunk_lean_degrees(const std::vector<Vec3>& points) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  if (points.empty()) return nan;
  const TreeBase base = find_base(points);
  const double h = base.height;
  if (!(h > 0)) return nan;
  const Vec3 b0 = base.low_centroid;
  const double z0 = base.axis.z;
  std::vector<Vec3> low;
  std::vector<double> low_r;
  for (const Vec3& p : points) {
    if (p.z <= z0 + kBaseShare * h) {
      low.push_back(p);
      low_r.push_back(std::hypot(p.x - b0.x, p.y - b0.y));
    }
  }
  const double w = std::max(h / kEnvelopeCells, 2 * median_of(low_r));
  return lean_from(points, b0, z0, h, w, low);
}

double trunk_lean_degrees(const std::vector<Vec3>& points, const Vec3& foot) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<Vec3> above, low;
  double top = foot.z;
  for (const Vec3& p : points) {
    if (p.z < foot.z) continue;
    above.push_back(p);
    top = std::max(top, p.z);
  }
  const double h = top - foot.z;
  if (!(h > 0)) return nan;
  for (const Vec3& p : above) {
    if (p.z <= foot.z + kBaseShare * h) low.push_back(p);
  }
  // A skeleton's trunk is a line: the window of the envelope's cell.
  return lean_from(above, foot, foot.z, h, h / kEnvelopeCells, low);
}

}  // namespace ramus::shape
