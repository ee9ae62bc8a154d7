#include "reconstruct/bsg/stem_tracking.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "reconstruct/bsg/centre_line.h"
#include "reconstruct/bsg/circle_fit.h"
#include "reconstruct/bsg/cylinder_fit.h"

namespace ramus::bsg {

namespace {

// The centre lines' acceptance (CentreLineParams) for a cylinder: 110 degrees of arc, half the
// points inliers, residual scale within 0.2 r, inliers along 60% of the piece (chain_cylinders).
constexpr double kMinCoverage = 1.9;
constexpr double kMinInliers = 0.5;
constexpr double kMaxResidual = 0.2;
constexpr double kMinFill = 0.6;
// A continuation of the trunk: it tapers, never thickens by more than noise, and bends little
// over one piece of two radii.
constexpr double kMinRatio = 0.6;
constexpr double kMaxRatio = 1.15;
const double kMinCosine = std::cos(15.0 * M_PI / 180.0);
// Pieces coasted straight through a whorl or an occluded stretch before the track stops.
constexpr int kMaxCoast = 3;
constexpr std::size_t kMinPoints = 12;
constexpr std::size_t kMaxPieces = 100000;
// What the track passes (rehang_on_track): within this many radii of its axis.
constexpr double kAbsorb = 1.25;

// The root's heaviest chain: from node 0, always the child with the largest subtree.
std::vector<std::uint32_t> heaviest_chain(const Bsg& b) {
  std::vector<std::uint32_t> order, main_child;
  tree_order(b.parent, order, main_child);
  std::vector<std::uint32_t> chain{0};
  for (std::uint32_t v = main_child[0]; v != kNone; v = main_child[v]) chain.push_back(v);
  return chain;
}

// Distance from x to the track's axis (a polyline), the interpolated radius there, the nearest
// track point, and whether x lies beyond the track's top end.
struct TrackDistance {
  double dist = std::numeric_limits<double>::infinity();
  double radius = 0;
  std::size_t nearest = 0;
  bool beyond_top = false;
};

TrackDistance distance_to_track(const StemTrack& t, const Eigen::Vector3d& x) {
  TrackDistance out;
  for (std::size_t j = 0; j + 1 < t.axis.size(); ++j) {
    const Eigen::Vector3d a = t.axis[j], ab = t.axis[j + 1] - a;
    const double l2 = ab.squaredNorm();
    const double s = l2 > 0 ? std::clamp((x - a).dot(ab) / l2, 0.0, 1.0) : 0.0;
    const double d = (x - a - s * ab).norm();
    if (d < out.dist) {
      out.dist = d;
      out.radius = t.radius[j] + s * (t.radius[j + 1] - t.radius[j]);
      out.nearest = s < 0.5 ? j : j + 1;
      const double past = l2 > 0 ? (x - a).dot(ab) / std::sqrt(l2) - std::sqrt(l2) : 0.0;
      out.beyond_top = j + 2 == t.axis.size() && past > out.radius;
    }
  }
  return out;
}

}  // namespace

StemTrack track_trunk(const Bsg& b, const std::vector<std::uint8_t>& fitted,
                      const PointIndex& index, const std::vector<Eigen::Vector3d>& samples,
                      const std::vector<double>& weight, double spacing, std::uint32_t& start) {
  StemTrack t;
  start = kNone;
  if (b.size() < 3 || fitted.size() != b.size() || !(spacing > 0)) return t;
  // The fitted base: the first run of at least three fitted nodes of the root's heaviest chain
  // that starts within its first quarter (ground and root flare may leave the lowest unfitted).
  const std::vector<std::uint32_t> chain = heaviest_chain(b);
  std::vector<double> along(chain.size(), 0.0);
  for (std::size_t i = 1; i < chain.size(); ++i) {
    along[i] = along[i - 1] + (b.pos[chain[i]] - b.pos[chain[i - 1]]).norm();
  }
  std::size_t first = 0, run = 0;
  for (std::size_t i = 0; i < chain.size() && along[i] <= 0.25 * along.back(); ++i) {
    if (!fitted[chain[i]]) continue;
    std::size_t j = i;
    while (j < chain.size() && fitted[chain[j]]) ++j;
    if (j - i >= 3) {
      first = i, run = j;
      break;
    }
    i = j;
  }
  if (run == 0) return t;
  const std::uint32_t s = chain[run - 1];
  double r = b.radius[s];
  // The base's direction over at least three radii of it (all of it when shorter).
  Eigen::Vector3d from = b.pos[chain[first]];
  for (std::size_t i = run - 1; i-- > first;) {
    if ((b.pos[s] - b.pos[chain[i]]).norm() >= 3 * r) {
      from = b.pos[chain[i]];
      break;
    }
  }
  Eigen::Vector3d d = b.pos[s] - from;
  if (!(r > 0) || !(d.norm() >= 2 * r)) return t;
  d.normalize();
  const Eigen::Vector3d base_direction = d;

  const double noise = 0.25 * spacing;
  t.axis.push_back(b.pos[s]);
  t.radius.push_back(r);
  t.fitted.push_back(1);
  Eigen::Vector3d p = b.pos[s];
  int misses = 0;
  std::vector<double> recent{r};
  std::vector<std::uint32_t> near;
  std::vector<Eigen::Vector3d> pts;
  std::vector<Eigen::Vector2d> section;
  std::vector<double> w;
  while (t.axis.size() < kMaxPieces && r >= 1.5 * spacing) {
    const double length = std::max(2 * r, 6 * spacing);
    const double span = 0.5 * length, reach = 1.5 * r + 2 * spacing;
    const Eigen::Vector3d centre = p + span * d, end = p + length * d;
    gather_cylinder(centre, d, reach, span, index, samples, weight, near, pts, w);
    bool ok = false;
    CylinderFit f;
    Eigen::Vector3d dir = d;
    if (pts.size() >= kMinPoints) {
      f = fit_cylinder(pts, w, centre, d, span, noise);
      if (f.valid) {
        dir = f.direction.dot(d) < 0 ? Eigen::Vector3d(-f.direction) : f.direction;
        const Eigen::Vector3d off = f.point - centre;
        const double shift = (off - off.dot(d) * d).norm();
        ok = f.coverage >= kMinCoverage && f.inlier_fraction >= kMinInliers &&
             f.residual <= kMaxResidual * f.radius + noise && f.axial_fill >= kMinFill &&
             f.radius >= kMinRatio * r && f.radius <= kMaxRatio * r + spacing &&
             dir.dot(d) >= kMinCosine && shift <= 0.5 * r + spacing;
      }
    }
    // A piece the free cylinder does not pass (it leans towards a whorl's branches, whose points
    // it takes for bark) is fitted once more as a cross-section across the predicted axis, as
    // the centre lines' continuation fits do (docs/reconstruction.md, Centre lines, step 5).
    if (!ok && pts.size() >= kMinPoints) {
      Eigen::Vector3d e1, e2;
      perpendicular_frame(d, e1, e2);
      section.clear();
      for (const Eigen::Vector3d& q : pts)
        section.emplace_back((q - centre).dot(e1), (q - centre).dot(e2));
      const CircleFit c = fit_circle(section, w, noise);
      if (c.valid && c.coverage >= kMinCoverage && c.inlier_fraction >= kMinInliers &&
          c.residual <= kMaxResidual * c.radius + noise && c.radius >= kMinRatio * r &&
          c.radius <= kMaxRatio * r + spacing && c.centre.norm() <= 0.5 * r + spacing) {
        ok = true;
        dir = d;
        f.point = centre + c.centre.x() * e1 + c.centre.y() * e2;
        f.radius = c.radius;
      }
    }
    if (ok) {
      p = f.point + (end - f.point).dot(dir) * dir;
      misses = 0;
      t.axis.push_back(p), t.radius.push_back(f.radius), t.fitted.push_back(1);
      // The next piece goes along the chord of the accepted axis over the last six radii (one
      // piece's fit tilts by a few degrees at a whorl; the chord does not drift with it).
      d = dir;
      for (std::size_t j = t.axis.size() - 1; j-- > 0;) {
        if (!t.fitted[j]) continue;
        const Eigen::Vector3d chord = p - t.axis[j];
        if (chord.norm() >= 6 * r) {
          d = chord.normalized();
          break;
        }
      }
      // The next piece is judged against the median of the last three accepted radii: a whorl's
      // bulge or a thin patch of bark moves one fit, not the trunk.
      recent.push_back(f.radius);
      if (recent.size() > 3) recent.erase(recent.begin());
      std::vector<double> sorted = recent;
      std::sort(sorted.begin(), sorted.end());
      r = sorted[sorted.size() / 2];
    } else {
      if (++misses > kMaxCoast) break;
      p = end;
      t.axis.push_back(p), t.radius.push_back(r), t.fitted.push_back(0);
    }
  }
  while (!t.fitted.empty() && !t.fitted.back()) {
    t.axis.pop_back(), t.radius.pop_back(), t.fitted.pop_back();
  }
  if (t.axis.size() < 2) return StemTrack{};
  start = s;
  // Below a fitted base that starts above the root (a root flare, undergrowth and ground around
  // the base, where the BSG's chain wanders), the trunk goes on straight down along the base's
  // direction to the root's level, and the root moves onto it.
  const double below = (b.pos[0] - b.pos[chain[first]]).dot(base_direction);
  if (first > 0 && below < 0) {
    StemTrack full;
    const double r_base = b.radius[chain[first]];
    const int pieces = std::max(1, int(std::ceil(-below / std::max(2 * r_base, 6 * spacing))));
    for (int k = 0; k < pieces; ++k) {
      full.axis.push_back(b.pos[chain[first]] +
                          below * (1.0 - double(k) / pieces) * base_direction);
      full.radius.push_back(r_base);
      full.fitted.push_back(0);
    }
    for (std::size_t i = first; i + 1 < run; ++i) {
      full.axis.push_back(b.pos[chain[i]]);
      full.radius.push_back(b.radius[chain[i]]);
      full.fitted.push_back(1);
    }
    for (std::size_t j = 0; j < t.axis.size(); ++j) {
      full.axis.push_back(t.axis[j]);
      full.radius.push_back(t.radius[j]);
      full.fitted.push_back(t.fitted[j]);
    }
    t = std::move(full);
    start = 0;
  }
  // Each point's radius is the median of its own and its neighbours' (the start's is its fit's):
  // one piece through a whorl's branch bases measures a bulge the trunk does not have.
  const std::vector<double> measured = t.radius;
  for (std::size_t j = 1; j < measured.size(); ++j) {
    double a = measured[j - 1], c = measured[j], e = j + 1 < measured.size() ? measured[j + 1] : c;
    t.radius[j] = std::max(std::min(a, c), std::min(std::max(a, c), e));
  }
  // A trunk does not thicken upwards (the pipe model): each point takes at most the radius below
  // it. Each piece may measure up to 1.15 x the last ones (noise, a whorl), and on treels_spruce
  // a run of such pieces at the track's top end grew a spindle of 0.13 m over a 0.08 m trunk.
  for (std::size_t j = 1; j < t.radius.size(); ++j) {
    t.radius[j] = std::min(t.radius[j], t.radius[j - 1]);
  }
  return t;
}

std::size_t rehang_on_track(Bsg& b, std::vector<std::uint8_t>& fitted, const StemTrack& track,
                            std::uint32_t start, double spacing) {
  const std::size_t n = b.size(), m = track.axis.size();
  if (m < 2 || start >= n || fitted.size() != n) return 0;
  // The start's descendants within the track's tube go.
  std::vector<std::uint8_t> below(n, 0), absorbed(n, 0);
  std::vector<TrackDistance> where(n);
  below[start] = 1;
  std::size_t removed = 0;
  for (std::uint32_t v = start + 1; v < n; ++v) {
    if (b.parent[v] == kNone || !below[b.parent[v]]) continue;
    below[v] = 1;
    where[v] = distance_to_track(track, b.pos[v]);
    if (!where[v].beyond_top && where[v].dist <= kAbsorb * where[v].radius + 2 * spacing) {
      absorbed[v] = 1;
      ++removed;
    }
  }
  // The new tree: the kept nodes in their order, then the track's points after the start.
  const std::uint32_t kept_count = std::uint32_t(n - removed);
  std::vector<std::uint32_t> local(n, kNone);
  Bsg out;
  std::vector<std::uint8_t> fit;
  for (std::uint32_t v = 0; v < n; ++v) {
    if (absorbed[v]) continue;
    local[v] = std::uint32_t(out.size());
    append_node(out, b, v, kNone);
    fit.push_back(fitted[v]);
  }
  // The start stands on the track's first point (the root, moved onto the trunk's axis when the
  // track was continued down to it; elsewhere it is there already).
  out.pos[local[start]] = track.axis[0];
  // Track point j (j >= 1) is node kept_count + j - 1; point 0 is the start.
  auto track_node = [&](std::size_t j) {
    return j == 0 ? local[start] : kept_count + std::uint32_t(j - 1);
  };
  for (std::size_t j = 1; j < m; ++j) {
    out.pos.push_back(track.axis[j]);
    out.parent.push_back(track_node(j - 1));
    out.vertex.push_back(kNone);
    out.weight.push_back(b.weight[start]);
    out.radius.push_back(track.radius[j]);
    out.mass.push_back(0.0);
    fit.push_back(track.fitted[j]);
  }
  for (std::uint32_t v = 1; v < n; ++v) {
    if (absorbed[v]) continue;
    const std::uint32_t u = b.parent[v];
    // A child of a removed node is itself below the start: its distance to the track is known.
    out.parent[local[v]] = absorbed[u] ? track_node(where[v].nearest) : local[u];
  }
  // Parents before children again.
  std::vector<std::uint32_t> old_of;
  b = depth_first(out, children_of(out.parent), &old_of);
  fitted.assign(old_of.size(), 0);
  for (std::size_t i = 0; i < old_of.size(); ++i) fitted[i] = fit[old_of[i]];
  return removed;
}

}  // namespace ramus::bsg
