#include "reconstruct/bsg/stem_tracking.h"

#include <Eigen/Eigenvalues>
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

// The nodes of the fitted base run that lie on one axis, in order along it. The centre lines fit
// each node on its own, and in a one-sided scan a few nodes of a trunk's chain are fitted to
// something else: a whorl's branch (the conifer from one station at 60 degrees: two nodes 0.25-
// 0.35 m off a 0.22 m trunk, one 0.5 m out on a 6 cm branch), or two stems at once above a fork
// (thick_oak at 180 degrees: a circle of 0.42 m across the leader and a limb, 0.34 m off the
// leader's axis). The track started at the run's last node along the direction of the last three
// radii, 45 degrees off the conifer's trunk. So: over the run's nodes within kBaseWindow radii of
// its first, the line from the first node through another that has the most nodes within a
// quarter of their radius (plus a spacing) of it (of equal counts the longer line; a trunk bends
// little over ten radii: a sagitta of a quarter radius needs a bend of radius 50 r, so a line is
// its axis there); beyond that window each node is kept when it lies within half its radius (the
// track's tolerance for a continuation) of the line fitted to the kept nodes of the last ten
// radii, which follows a trunk that curves.
constexpr double kBaseWindow = 10.0;
constexpr double kOnLine = 0.25;
constexpr double kOnChord = 0.5;

// The least-squares line through `points`: their centroid and principal direction (zero when
// they do not span one).
void fit_line(const std::vector<Eigen::Vector3d>& points, Eigen::Vector3d& mean,
              Eigen::Vector3d& dir) {
  mean.setZero();
  dir.setZero();
  if (points.empty()) return;
  for (const Eigen::Vector3d& p : points) mean += p;
  mean /= double(points.size());
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (const Eigen::Vector3d& p : points) cov += (p - mean) * (p - mean).transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
  if (eig.eigenvalues()(2) > 0) dir = eig.eigenvectors().col(2);
}

// The same through the nodes `line` of `b`.
void fit_line(const Bsg& b, const std::vector<std::uint32_t>& line, Eigen::Vector3d& mean,
              Eigen::Vector3d& dir) {
  std::vector<Eigen::Vector3d> points;
  for (std::uint32_t v : line) points.push_back(b.pos[v]);
  fit_line(points, mean, dir);
}

std::vector<std::uint32_t> base_on_axis(const Bsg& b, const std::vector<std::uint32_t>& run,
                                        double spacing) {
  auto within = [&](std::uint32_t v, const Eigen::Vector3d& a, const Eigen::Vector3d& dir,
                    double share) {
    const Eigen::Vector3d x = b.pos[v] - a;
    return (x - x.dot(dir) * dir).norm() <= share * b.radius[v] + spacing;
  };
  const Eigen::Vector3d origin = b.pos[run.front()];
  const double window = kBaseWindow * b.radius[run.front()];
  std::size_t in_window = 1;
  while (in_window < run.size() && (b.pos[run[in_window]] - origin).norm() <= window) ++in_window;
  std::vector<std::uint8_t> keep(run.size(), 0);
  keep[0] = 1;
  std::size_t best = 0, best_count = 1;
  double best_length = 0;
  for (std::size_t k = 1; k < in_window; ++k) {
    const Eigen::Vector3d dir = b.pos[run[k]] - origin;
    const double length = dir.norm();
    if (!(length > 0)) continue;
    std::size_t count = 0;
    for (std::size_t i = 0; i < in_window; ++i)
      count += within(run[i], origin, dir / length, kOnLine);
    if (count > best_count || (count == best_count && length > best_length)) {
      best = k, best_count = count, best_length = length;
    }
  }
  if (best == 0) {
    std::fill(keep.begin(), keep.end(), 1);  // nothing to judge by: the run as it is
  } else {
    const Eigen::Vector3d dir = (b.pos[run[best]] - origin) / best_length;
    for (std::size_t i = 1; i < in_window; ++i) keep[i] = within(run[i], origin, dir, kOnLine);
    std::size_t last = 0;
    for (std::size_t i = 1; i < in_window; ++i) last = keep[i] ? i : last;
    for (std::size_t i = in_window; i < run.size(); ++i) {
      // The line fitted to the kept nodes within kBaseWindow radii below the last kept one (a
      // trunk bends little over ten radii, above), each judged against the line through the
      // others first. The chord of the last three radii followed a drift of a few centimetres
      // a node: on treels_spruce four nodes 5-16 cm off its 8 cm trunk at 6 m were kept one
      // after the other, and then every node above, back on the axis, was not.
      const double r_last = b.radius[run[last]];
      Eigen::Vector3d mean;
      std::vector<std::uint32_t> line;
      for (std::size_t j = last + 1; j-- > 0;) {
        if (!keep[j]) continue;
        if ((b.pos[run[last]] - b.pos[run[j]]).norm() > kBaseWindow * r_last) break;
        line.push_back(run[j]);
      }
      Eigen::Vector3d dir = Eigen::Vector3d::Zero();
      fit_line(b, line, mean, dir);
      // A node off the axis by more than a quarter radius (the first of a drift, kept within half
      // a radius) tilts a line of a few nodes towards it: the line again without such nodes.
      if (line.size() >= 4) {
        std::vector<std::uint32_t> on, others;
        Eigen::Vector3d m, e;
        for (std::uint32_t v : line) {
          others.clear();
          for (std::uint32_t o : line)
            if (o != v) others.push_back(o);
          fit_line(b, others, m, e);
          if (e.norm() == 0 || within(v, m, e, kOnLine)) on.push_back(v);
        }
        if (on.size() >= 2 && on.size() < line.size()) line = on, fit_line(b, line, mean, dir);
      }
      keep[i] = line.size() >= 2 && dir.norm() > 0 ? within(run[i], mean, dir, kOnChord) : 1;
      if (keep[i]) last = i;
    }
  }
  std::vector<std::uint32_t> kept;
  for (std::size_t i = 0; i < run.size(); ++i) {
    if (keep[i]) kept.push_back(run[i]);
  }
  // In order along the axis (a chain may step back along it; the track must not). A run with
  // every node on the axis stays as it is.
  if (kept.size() == run.size()) return kept;
  const Eigen::Vector3d axis = b.pos[kept.back()] - origin;
  std::stable_sort(kept.begin() + 1, kept.end(), [&](std::uint32_t u, std::uint32_t v) {
    return (b.pos[u] - origin).dot(axis) < (b.pos[v] - origin).dot(axis);
  });
  return kept;
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
  // The base's nodes on one axis (base_on_axis); the track starts from the last of them. A run
  // that goes on off that axis for two fitted nodes or more goes on along another stem: the
  // trunk's chain turned into a limb at a fork (thick_oak from one station at 120 degrees: 46
  // nodes on a 27 cm limb), and the base is taken as it is, as the track's start has always been
  // (a track from the last node on the axis, below the fork, spanned the stems that leave it
  // with the trunk's radius and went 0.3 m off the leader). One fitted node off the axis at the
  // run's end is one cross-section, cut through the base of a whorl's branch the chain stepped
  // onto (treels_spruce once its stray points were ignored: one node 0.27 m off its 12 cm trunk,
  // and a track from it stopped after four pieces), and the track starts on the axis.
  const std::vector<std::uint32_t> run_nodes(chain.begin() + first, chain.begin() + run);
  std::vector<std::uint32_t> base = base_on_axis(b, run_nodes, spacing);
  const std::size_t tail =
      base.empty() ? run_nodes.size()
                   : std::size_t(std::find(run_nodes.rbegin(), run_nodes.rend(), base.back()) -
                                 run_nodes.rbegin());
  if (tail >= 2) base = run_nodes;
  const bool wandered = base.size() < run_nodes.size();
  const std::uint32_t s = base.back();
  double r = b.radius[s];
  if (wandered) {
    // The radii were smoothed with the neighbours' (smooth_fitted_radii), the wandering nodes'
    // among them: the conifer's base ends at 0.14 m on a 0.21 m trunk. The median of the last
    // five kept nodes.
    std::vector<double> last;
    for (std::size_t i = base.size(); i-- > 0 && last.size() < 5;)
      last.push_back(b.radius[base[i]]);
    std::sort(last.begin(), last.end());
    r = last[last.size() / 2];
  }
  // The base's direction over at least three radii of it (all of it when shorter).
  Eigen::Vector3d from = b.pos[base.front()];
  for (std::size_t i = base.size() - 1; i-- > 0;) {
    if ((b.pos[s] - b.pos[base[i]]).norm() >= 3 * r) {
      from = b.pos[base[i]];
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
  if (t.axis.size() < 2 && !wandered) return StemTrack{};
  start = s;
  // Below a fitted base that starts above the root (a root flare, undergrowth and ground around
  // the base, where the BSG's chain wanders), the trunk goes on straight down along the base's
  // direction to the root's level, and the root moves onto it. A base with nodes off its axis
  // becomes part of the track too, from its first node, so that those nodes are replaced.
  const double below = (b.pos[0] - b.pos[chain[first]]).dot(base_direction);
  const bool extend_down = first > 0 && below < 0;
  if (extend_down || wandered) {
    StemTrack full;
    const double r_base = b.radius[chain[first]];
    const int pieces =
        extend_down ? std::max(1, int(std::ceil(-below / std::max(2 * r_base, 6 * spacing)))) : 0;
    // Down along the line fitted to the base's nodes on the axis and the track's fitted points
    // within 20 base radii of its start (a direction over its last three radii, extrapolated a
    // few metres down, tilted the root off the trunk; a base of a metre, its lowest fits widened
    // by the flare, did too: treels_spruce's root 0.18 m off its trunk).
    std::vector<Eigen::Vector3d> stretch;
    for (std::uint32_t v : base) stretch.push_back(b.pos[v]);
    for (std::size_t j = 0; j < t.axis.size(); ++j) {
      if ((t.axis[j] - b.pos[base.front()]).norm() > 20 * r_base) break;
      if (t.fitted[j]) stretch.push_back(t.axis[j]);
    }
    Eigen::Vector3d mean, dir;
    fit_line(stretch, mean, dir);
    const bool fitted_line = stretch.size() >= 3 && dir.norm() > 0;
    if (fitted_line && dir.dot(base_direction) < 0) dir = -dir;
    const Eigen::Vector3d top =
        fitted_line ? Eigen::Vector3d(mean + (b.pos[chain[first]] - mean).dot(dir) * dir)
                    : b.pos[chain[first]];
    const Eigen::Vector3d down = fitted_line ? dir : base_direction;
    for (int k = 0; k < pieces; ++k) {
      full.axis.push_back(top + below * (1.0 - double(k) / pieces) * down);
      full.radius.push_back(r_base);
      full.fitted.push_back(0);
    }
    for (std::size_t i = 0; i + 1 < base.size(); ++i) {
      full.axis.push_back(b.pos[base[i]]);
      full.radius.push_back(b.radius[base[i]]);
      full.fitted.push_back(1);
    }
    for (std::size_t j = 0; j < t.axis.size(); ++j) {
      full.axis.push_back(t.axis[j]);
      full.radius.push_back(t.radius[j]);
      full.fitted.push_back(t.fitted[j]);
    }
    t = std::move(full);
    start = extend_down ? 0 : chain[first];
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
