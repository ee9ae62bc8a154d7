#include "reconstruct/bsg/centre_line.h"

#include <tbb/parallel_for.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "reconstruct/bsg/bsg.h"
#include "reconstruct/bsg/chain_cylinders.h"
#include "reconstruct/bsg/circle_fit.h"
#include "reconstruct/bsg/kdtree.h"
#include "reconstruct/bsg/one_sided_sections.h"

namespace ramus::bsg {

void gather_slab(const Eigen::Vector3d& x, const Eigen::Vector3d& d, const Eigen::Vector3d& e1,
                 const Eigen::Vector3d& e2, double reach, double half, const PointIndex& index,
                 const std::vector<Eigen::Vector3d>& samples, const std::vector<double>& weight,
                 std::vector<std::uint32_t>& near, std::vector<Eigen::Vector2d>& pts,
                 std::vector<double>& w) {
  near.clear(), pts.clear(), w.clear();
  index.within_slab(x, std::sqrt(reach * reach + half * half), d, half, near);
  for (std::uint32_t i : near) {
    const Eigen::Vector3d q = samples[i] - x;
    if (std::abs(q.dot(d)) > half) continue;
    const Eigen::Vector2d uv(q.dot(e1), q.dot(e2));
    if (uv.squaredNorm() > reach * reach) continue;
    pts.push_back(uv);
    w.push_back(weight.empty() ? 1.0 : weight[i]);
  }
}

void gather_cylinder(const Eigen::Vector3d& x, const Eigen::Vector3d& d, double reach, double half,
                     const PointIndex& index, const std::vector<Eigen::Vector3d>& samples,
                     const std::vector<double>& weight, std::vector<std::uint32_t>& near,
                     std::vector<Eigen::Vector3d>& pts, std::vector<double>& w) {
  near.clear(), pts.clear(), w.clear();
  index.within(x, std::sqrt(reach * reach + half * half), near);
  for (std::uint32_t i : near) {
    const Eigen::Vector3d q = samples[i] - x;
    const double t = q.dot(d);
    if (std::abs(t) > half || (q - t * d).squaredNorm() > reach * reach) continue;
    pts.push_back(samples[i]);
    w.push_back(weight.empty() ? 1.0 : weight[i]);
  }
}

void thin_slab(std::vector<Eigen::Vector2d>& pts, std::vector<double>& w, int max_points) {
  if (max_points <= 0 || int(pts.size()) <= max_points) return;
  const std::size_t stride = (pts.size() + max_points - 1) / max_points;
  std::size_t k = 0;
  for (std::size_t i = 0; i < pts.size(); i += stride) pts[k] = pts[i], w[k] = w[i], ++k;
  pts.resize(k), w.resize(k);
}

namespace {

// cos 15 degrees: directions this close cut a stem in nearly the same slab.
constexpr double kSameDirection = 0.966;

struct SlabFit {
  bool ok = false;
  Eigen::Vector3d axis_point;
  double radius = 0;
  double residual = 0;  // the accepted circle's residual scale
  // Where no circle fits the whole slab but its points fall into separate groups (two limbs
  // side by side after their fork, each seen on one side): the circle of the group the node
  // belongs to, which centre_line takes if it continues the stem below.
  bool own_ok = false;
  Eigen::Vector3d own_point;
  double own_radius = 0;
  bool own_from_arcs = false;  // the own circle is one of two touching arcs (split_two_arcs)
};

// The local branch direction at v: from two nodes up to two nodes down the heaviest child (the
// child with the largest subtree), which smooths the zig-zags of single edges.
Eigen::Vector3d direction_at(std::uint32_t v, const std::vector<Eigen::Vector3d>& pos,
                             const std::vector<std::uint32_t>& parent,
                             const std::vector<std::uint32_t>& main_child,
                             const std::vector<std::uint8_t>& fork) {
  std::uint32_t a = v, b = v;
  for (int k = 0; k < 2; ++k) {
    if (parent[a] != kNone) a = parent[a];
    // At a fork the way out may be a limb as heavy as the stem; the way in is the stem.
    if (main_child[b] != kNone && (!fork[v] || a == v)) b = main_child[b];
  }
  Eigen::Vector3d d = pos[b] - pos[a];
  if (!(d.norm() > 0)) return Eigen::Vector3d::UnitZ();
  return d.normalized();
}

// Labels the points by connected group (points closer than `link` chain together; each point's
// label is the first index of its group) and returns the number of groups. A sweep along the
// first coordinate compares only points less than `link` apart in it.
int group_points(const std::vector<Eigen::Vector2d>& pts, double link,
                 std::vector<std::uint32_t>& label) {
  const std::uint32_t m = std::uint32_t(pts.size());
  thread_local std::vector<std::uint32_t> by_x;
  by_x.resize(m);
  label.resize(m);
  for (std::uint32_t i = 0; i < m; ++i) label[i] = by_x[i] = i;
  std::sort(by_x.begin(), by_x.end(), [&](std::uint32_t a, std::uint32_t b) {
    return pts[a].x() < pts[b].x() || (pts[a].x() == pts[b].x() && a < b);
  });
  auto root = [&](std::uint32_t i) {
    while (label[i] != i) i = label[i] = label[label[i]];
    return i;
  };
  const double l2 = link * link;
  for (std::uint32_t k = 0; k < m; ++k) {
    const std::uint32_t i = by_x[k];
    for (std::uint32_t q = k + 1; q < m && pts[by_x[q]].x() - pts[i].x() <= link; ++q) {
      const std::uint32_t j = by_x[q];
      if ((pts[i] - pts[j]).squaredNorm() > l2) continue;
      const std::uint32_t a = root(i), b = root(j);
      if (a != b) label[std::max(a, b)] = std::min(a, b);  // the smaller index stays the root
    }
  }
  int groups = 0;
  for (std::uint32_t i = 0; i < m; ++i) groups += (label[i] = root(i)) == i;
  return groups;
}

// Fits the cross-section at `x` (direction d). The search disc grows when the circle reaches
// beyond it: a node on the bark of a stem thicker than its radius hint sees only part of it.
SlabFit fit_slab(const Eigen::Vector3d& x, const Eigen::Vector3d& d, double hint,
                 const PointIndex& index, const std::vector<Eigen::Vector3d>& samples,
                 const std::vector<double>& weight, const CentreLineParams& p, double noise) {
  SlabFit out;
  Eigen::Vector3d e1, e2;
  perpendicular_frame(d, e1, e2);
  // The first disc is at most 20 spacings wide (a generous hint would gather thousands of points
  // for every node); it grows below when the circle reaches beyond it.
  double r0 = std::clamp(hint, 2 * p.spacing, 20 * p.spacing);
  // Per-thread buffers: thousands of slabs are fitted, each in up to four attempts.
  thread_local std::vector<std::uint32_t> near;
  thread_local std::vector<Eigen::Vector2d> pts;
  thread_local std::vector<double> w;
  thread_local std::vector<std::uint32_t> label;
  thread_local std::vector<Eigen::Vector2d> group_pts;
  thread_local std::vector<double> group_w;
  double thicken = 1;  // a sparse slab (a thin branch far from the scanner) is taken thicker once
  for (int attempt = 0; attempt < 4; ++attempt) {
    const double reach = std::max(2.5 * r0, 5 * p.spacing);
    const double half = thicken * std::max(0.3 * r0, 1.5 * p.spacing);
    gather_slab(x, d, e1, e2, reach, half, index, samples, weight, near, pts, w);
    if (pts.size() < 8 && thicken == 1 && pts.size() >= 3) {
      thicken = 2;
      continue;
    }
    if (pts.size() < 8) return out;
    thin_slab(pts, w, p.max_slab_points);
    // A radius far above the hint is a flat arc (a scan's edge, a wall of twigs), not a stem.
    auto stem_sized = [&](const CircleFit& f) {
      return f.valid && f.radius <= p.max_hint_factor * std::max(hint, 2 * p.spacing);
    };
    // The residual and inlier limits of a stem's section: the circle fits its points.
    auto fits_points = [&](const CircleFit& f) {
      return f.residual <= p.max_residual * f.radius + noise && f.inlier_fraction >= p.min_inliers;
    };
    // A circle is a stem's cross-section when it is a plausible size and its inliers cover
    // enough arc closely, around a centre not too far from the node.
    auto good = [&](const CircleFit& f, double within) {
      return stem_sized(f) && fits_points(f) && f.coverage >= p.min_coverage &&
             f.radius >= p.spacing && f.centre.norm() + f.radius <= within &&
             f.centre.norm() <= p.max_shift * f.radius + 2 * p.spacing;
    };
    const CircleFit f = fit_circle(pts, w, noise);
    // A wider disc only for a circle that fits its points: one that misses them is no section the
    // disc cut off, and a wider disc gathers more of what it misses. On the sparse crown of
    // adtree_ahn3_delft 63 of 157 discs were regrown for such circles, 10% of the
    // reconstruction's time.
    if (stem_sized(f) && fits_points(f) && f.centre.norm() + f.radius > 0.9 * reach &&
        attempt < 3) {
      r0 = std::min(2 * r0, 1.3 * std::max(f.radius, f.centre.norm()));
      continue;
    }
    if (good(f, reach)) {
      out.ok = true;
      out.axis_point = x + f.centre.x() * e1 + f.centre.y() * e2;
      out.radius = f.radius;
      out.residual = f.residual;
      return out;
    }
    // No circle fits the slab. Where its points fall into groups, told apart by gaps wider than
    // half the radius the disc is sized for (the bark of one stem is continuous at the scan's
    // spacing, and a twig's shadow on it is narrower), one group may be the node's own stem.
    // Only for stems of at least three spacings: thinner ones show no arcs to fit apart, and a
    // sparse scan's slabs fall into groups of a few points that cost fits and give none.
    if (!p.separate_stems || hint < 3 * p.spacing) return out;
    // The circle nearest the node (distance to its disc; the node starts on the bark of its
    // stem), the larger of two that hold the node. Within 0.9 of the disc: a circle that reaches
    // its edge may be cut off by it.
    double best = 0;
    auto consider = [&](const CircleFit& c) {
      if (!good(c, 0.9 * reach)) return;
      const double off = std::max(c.centre.norm() - c.radius, 0.0);
      if (out.own_ok && (off > best || (off == best && c.radius <= out.own_radius))) return;
      out.own_ok = true, best = off;
      out.own_point = x + c.centre.x() * e1 + c.centre.y() * e2;
      out.own_radius = c.radius;
    };
    if (group_points(pts, std::max(3 * p.spacing, 0.5 * r0), label) >= 2) {
      for (std::uint32_t g = 0; g < pts.size(); ++g) {
        if (label[g] != g) continue;
        group_pts.clear(), group_w.clear();
        for (std::size_t i = g; i < pts.size(); ++i) {
          if (label[i] == g) group_pts.push_back(pts[i]), group_w.push_back(w[i]);
        }
        if (group_pts.size() >= 8) consider(fit_circle(group_pts, group_w, noise));
      }
    }
    // No group is a stem: the limbs' arcs may touch (just after their fork), so that no gap
    // parts them; split where one arc ends.
    CircleFit a, b;
    if (!out.own_ok && p.split_arcs && split_two_arcs(pts, w, f, noise, a, b)) {
      consider(a), consider(b);
      out.own_from_arcs = out.own_ok;
    }
    return out;
  }
  return out;
}

}  // namespace

void tree_order(const std::vector<std::uint32_t>& parent, std::vector<std::uint32_t>& order,
                std::vector<std::uint32_t>& main_child) {
  const std::size_t n = parent.size();
  std::vector<std::vector<std::uint32_t>> ch(n);
  order.clear();
  for (std::uint32_t v = 0; v < n; ++v) {
    if (parent[v] == kNone || parent[v] >= n) {
      order.push_back(v);
    } else {
      ch[parent[v]].push_back(v);
    }
  }
  for (std::size_t i = 0; i < order.size(); ++i) {
    for (std::uint32_t c : ch[order[i]]) order.push_back(c);
  }
  std::vector<std::size_t> size(n, 1);
  for (std::size_t i = order.size(); i-- > 0;) {
    const std::uint32_t v = order[i];
    if (parent[v] != kNone && parent[v] < n) size[parent[v]] += size[v];
  }
  main_child.assign(n, kNone);
  for (std::uint32_t v = 0; v < n; ++v) {
    for (std::uint32_t c : ch[v]) {
      if (main_child[v] == kNone || size[c] > size[main_child[v]]) main_child[v] = c;
    }
  }
}

CentreLineResult centre_line(std::vector<Eigen::Vector3d>& pos,
                             const std::vector<std::uint32_t>& parent,
                             const std::vector<double>& radius,
                             const std::vector<Eigen::Vector3d>& samples, const PointIndex& index,
                             const std::vector<double>& sample_weight, const CentreLineParams& p) {
  const std::size_t n = pos.size();
  CentreLineResult res;
  res.fitted.assign(n, 0);
  res.radius.assign(n, 0.0);
  if (n == 0 || samples.size() < 8 || !(p.spacing > 0)) return res;
  std::vector<std::uint32_t> order, main_child;
  tree_order(parent, order, main_child);
  std::vector<std::uint8_t> fork(n, 0);
  {
    std::vector<int> children(n, 0);
    for (std::uint32_t v = 0; v < n; ++v) {
      if (parent[v] < n) ++children[parent[v]];
    }
    for (std::uint32_t v = 0; v < n; ++v) fork[v] = children[v] > 1;
  }
  const double noise = p.noise > 0 ? p.noise : 0.25 * p.spacing;
  const std::vector<Eigen::Vector3d> original = pos;
  std::vector<SlabFit> fits(n);
  // A fork whose slab could not be fitted (it cuts the stem and its branches at once) lies on
  // the stem's axis: the line through the two fitted nodes below it, when it is near that line.
  auto repair_forks = [&] {
    for (std::uint32_t v : order) {
      if (!fork[v] || fits[v].ok) continue;
      const std::uint32_t u = parent[v];
      if (u >= n || !fits[u].ok || parent[u] >= n || !fits[parent[u]].ok) continue;
      const Eigen::Vector3d a = pos[parent[u]], d = pos[u] - a;
      if (!(d.squaredNorm() > 0)) continue;
      const Eigen::Vector3d on = a + d * ((original[v] - a).dot(d) / d.squaredNorm());
      if ((on - original[v]).norm() <= 1.5 * fits[u].radius + p.spacing) pos[v] = on;
    }
  };
  // A root (the trunk's foot: the base finder takes the scan's vertex nearest the footprint's
  // centroid, on the bark a one-sided scan sees) left unfitted below a fitted stem: onto that
  // stem's axis, the line through the first two fitted nodes up its heaviest chain two radii
  // apart or more, continued down to the root's level, when the root lies within 1.5 of their
  // radius of it. Left on the bark, the trunk's first edge ran across it (the 14 m harness tree
  // at 60 degrees: 0.59 m across a 0.58 m trunk, a bulb at its foot in the mesh), and the slabs
  // of the first nodes above it, across the direction from it, cut the stem obliquely. After
  // each pass, so that the next one takes its directions from the root on the axis, and last.
  auto centre_roots = [&] {
    if (!p.centre_roots) return;
    for (std::uint32_t root : order) {
      if (parent[root] < n) break;  // the roots come first in `order`
      if (fits[root].ok) continue;
      std::uint32_t lower = kNone, upper = kNone;
      for (std::uint32_t v = main_child[root], k = 0; v != kNone && k < 8; v = main_child[v], ++k) {
        if (!fits[v].ok) continue;
        if (lower == kNone) {
          lower = v;
        } else if ((pos[v] - pos[lower]).norm() >= 2 * fits[lower].radius) {
          upper = v;
          break;
        }
      }
      if (upper == kNone) continue;
      // Down to the root's level along a stem that rises (within 37 degrees of the vertical; a
      // sparse scan's stem may lean anywhere, and continued down it passed metres off the root).
      const Eigen::Vector3d d = (pos[upper] - pos[lower]).normalized();
      if (d.z() < 0.8 || pos[root].z() > pos[lower].z()) continue;
      const Eigen::Vector3d on = pos[lower] + d * ((pos[root].z() - pos[lower].z()) / d.z());
      if ((on - pos[root]).norm() > 1.5 * fits[lower].radius + p.spacing) continue;
      pos[root] = on;
      fits[root].ok = true, fits[root].axis_point = on, fits[root].radius = fits[lower].radius;
    }
  };
  for (int pass = 0; pass < std::max(1, p.passes); ++pass) {
    // Every node is fitted from the positions of the previous pass (Jacobi: the result does not
    // depend on the order or the thread count).
    const std::vector<Eigen::Vector3d> from = pass == 0 ? original : pos;
    tbb::parallel_for(std::size_t(0), n, [&](std::size_t v) {
      // Twigs thinner than the spacing cannot be fitted (and the axis projection has already
      // centred them); a second pass refits only what the first one fitted.
      if (pass == 0 ? radius[v] < p.min_hint_spacings * p.spacing : !fits[v].ok) return;
      const double hint = pass == 0 ? radius[v] : fits[v].radius;
      const Eigen::Vector3d d = direction_at(std::uint32_t(v), from, parent, main_child, fork);
      fits[v] = fit_slab(from[v], d, hint, index, samples, sample_weight, p, noise);
    });
    // Plausibility along the branches, parents first: no thickening outwards.
    // A firm circle (residual scale at most half the acceptance bound: a clean ring) is measured
    // against the nearest firm one below it, the others against the nearest accepted one. A
    // circle accepted near the bound may be an oblique cut's ellipse, too small, and must not
    // veto the clean rings of its stem above it: thick_oak grown from seed 5, one station, where
    // the fork node at the trunk's foot, its slab across a 47-degree edge from the root, took a
    // 0.43 m circle at 0.11 r, and every trunk ring above it up to 4 m (0.55-0.59 m at 0.01 r)
    // failed against it. Loose circles stay bounded by the nearest accepted one: measured against
    // the firm ones below them too, twigs took circles of their trunk (a branch of the spruce's
    // flood-fill skeleton 0.09 -> 0.3 m) and chains of the airborne scan moved metres.
    std::vector<std::uint32_t> fitted_below(n, kNone);  // the nearest accepted node, v or down
    std::vector<std::uint32_t> firm_below(n, kNone);    // the nearest firm one, v or down
    auto firm_circle = [&](std::uint32_t v) {
      return fits[v].ok && fits[v].residual <= 0.5 * p.max_residual * fits[v].radius + noise;
    };
    for (std::uint32_t v : order) {
      const std::uint32_t u = parent[v] < n ? parent[v] : kNone;
      // The radius of the nearest accepted ancestor (0: none).
      const std::uint32_t below = u == kNone ? kNone : fitted_below[u];
      const double ra = below == kNone ? 0.0 : fits[below].radius;
      const std::uint32_t firm = u == kNone ? kNone : firm_below[u];
      const double reference = firm != kNone && firm_circle(v) ? fits[firm].radius : ra;
      if (fits[v].ok && ra > 0 && fits[v].radius > p.max_section_growth * reference + p.spacing)
        fits[v].ok = false;
      // The slab found no stem, but one of its groups is a circle that continues the stem
      // below: the limb the node belongs to, beside another. Its radius is between the pipe
      // model's bounds, so that a twig's circle does not stand for a stem, nor do groups thicken
      // a stem step by step.
      // A circle of two touching arcs must also continue the axis below (within its radius of
      // the line through the two nearest fitted nodes down): next to a fork the node may lie on
      // the bark between both limbs, nearer the other one.
      const SlabFit& f = fits[v];
      bool continues = true;
      if (!f.ok && f.own_ok && f.own_from_arcs && below != kNone) {
        const std::uint32_t a = below;
        const std::uint32_t b = parent[a] < n ? fitted_below[parent[a]] : kNone;
        if (b != kNone) {
          const Eigen::Vector3d axis = fits[a].axis_point - fits[b].axis_point;
          const Eigen::Vector3d q = f.own_point - fits[b].axis_point;
          if (axis.squaredNorm() > 0) {
            const Eigen::Vector3d off = q - axis * (q.dot(axis) / axis.squaredNorm());
            continues = off.norm() <= ra + p.spacing;
          }
        }
      }
      if (!f.ok && f.own_ok && continues && ra > 0 && f.own_radius >= kPipeChild * ra &&
          f.own_radius <= ra) {
        fits[v].ok = true, fits[v].axis_point = f.own_point, fits[v].radius = f.own_radius;
        // Firm: it continues the stem below within the pipe model's bounds.
        fits[v].residual = 0;
      }
      firm_below[v] = firm_circle(v) ? v : firm;
      fitted_below[v] = fits[v].ok ? v : below;
    }
    for (std::size_t v = 0; v < n; ++v) pos[v] = fits[v].ok ? fits[v].axis_point : original[v];
    repair_forks();
    centre_roots();
  }
  // Stems whose chain zigzags: on a conifer's trunk scanned from one side the shortest paths
  // step from whorl to whorl across the bark, so the direction from two nodes up and down leans
  // 40-50 degrees off the stem and the slab cuts it obliquely (an ellipse, no circle fits). A
  // node that continues a fitted stem (its heaviest-child line leads down to two fitted nodes)
  // is fitted again across the axis of that stem (Livny et al. 2010, 4.2: branches are smooth),
  // parents first, so each fit carries the axis to the next node.
  if (p.continuation_fits) {
    const double thin = p.min_hint_spacings * p.spacing;
    std::vector<double> thickest_child(n, 0.0);
    for (std::uint32_t v = 0; v < n; ++v) {
      if (parent[v] < n) thickest_child[parent[v]] = std::max(thickest_child[parent[v]], radius[v]);
    }
    for (std::uint32_t v : order) {
      if (fits[v].ok || fork[v] || radius[v] < thin) continue;
      std::uint32_t lower = kNone, below = kNone;  // the nearest fitted node down and one beneath
      for (std::uint32_t c = v, k = 0; k < 8; ++k) {
        const std::uint32_t u = parent[c];
        // Down the stem only: through forks where this chain is the thickest way on.
        if (u >= n || main_child[u] != c || radius[c] < thickest_child[u]) break;
        c = u;
        if (!fits[u].ok) continue;
        if (lower == kNone) {
          lower = u;
        } else if ((pos[lower] - pos[u]).norm() >= 2 * std::max(fits[lower].radius, p.spacing)) {
          below = u;
          break;
        }
      }
      if (below == kNone) continue;
      const Eigen::Vector3d d = (pos[lower] - pos[below]).normalized();
      // Where the chain runs along the stem, the passes above tried this slab already.
      if (direction_at(v, original, parent, main_child, fork).dot(d) > kSameDirection) continue;
      const SlabFit f =
          fit_slab(original[v], d, fits[lower].radius, index, samples, sample_weight, p, noise);
      if (!f.ok || f.radius > p.max_growth * fits[lower].radius + p.spacing) continue;
      // The stem continues: the new axis point lies near the line of the fitted stem below (a
      // slab that cut a fork fits the limb or the crotch, off that line).
      const Eigen::Vector3d off = f.axis_point - pos[lower];
      if ((off - off.dot(d) * d).norm() > 0.25 * fits[lower].radius + p.spacing) continue;
      fits[v] = f;
      pos[v] = f.axis_point;
    }
  }
  // Chains whose cross-sections failed: cylinders along them (chain_cylinders.h).
  if (p.chain_cylinders) {
    std::vector<std::uint8_t> ok(n);
    std::vector<double> r(n);
    for (std::size_t v = 0; v < n; ++v) ok[v] = fits[v].ok, r[v] = fits[v].radius;
    if (fit_chain_cylinders(pos, parent, radius, ok, r, index, samples, sample_weight, p, noise) >
        0) {
      for (std::size_t v = 0; v < n; ++v) {
        if (ok[v] && !fits[v].ok)
          fits[v].ok = true, fits[v].axis_point = pos[v], fits[v].radius = r[v];
      }
      repair_forks();
    }
  }
  // Nodes still without a fit on a branch fitted elsewhere: one-sided arcs with the branch's
  // radius (one_sided_sections.h).
  if (p.one_sided_sections) {
    std::vector<std::uint8_t> ok(n);
    std::vector<double> r(n);
    for (std::size_t v = 0; v < n; ++v) ok[v] = fits[v].ok, r[v] = fits[v].radius;
    const double thin = p.min_hint_spacings * p.spacing;
    // The bridges again: the new fits end runs of unfitted nodes that were too long before.
    std::size_t moved =
        fit_one_sided_sections(pos, parent, radius, ok, r, index, samples, sample_weight, p, noise);
    // Eight nodes either way: the runs left are those across occluded stretches (thick_oak from
    // one station: 4-6 nodes up and down); the distance test keeps other branches' nodes off.
    moved += bridge_unfitted(pos, parent, radius, ok, r, p.spacing, thin, 8);
    if (moved > 0) {
      for (std::size_t v = 0; v < n; ++v) {
        if (ok[v] && !fits[v].ok)
          fits[v].ok = true, fits[v].axis_point = pos[v], fits[v].radius = r[v];
      }
      repair_forks();
    }
  }
  centre_roots();
  for (std::size_t v = 0; v < n; ++v) {
    res.fitted[v] = fits[v].ok;
    res.radius[v] = fits[v].ok ? fits[v].radius : 0.0;
    res.fitted_count += fits[v].ok;
  }
  return res;
}

void subdivide_long_edges(Bsg& b, double spacing, double min_radius, double edge_radii,
                          double edge_spacings) {
  if (b.size() < 2) return;
  Bsg out;
  std::vector<std::uint32_t> local(b.size(), kNone);
  auto push = [&](const Eigen::Vector3d& pos, std::uint32_t parent, std::uint32_t vertex,
                  double weight, double radius, double mass) {
    out.pos.push_back(pos), out.parent.push_back(parent), out.vertex.push_back(vertex);
    out.weight.push_back(weight), out.radius.push_back(radius), out.mass.push_back(mass);
    return std::uint32_t(out.pos.size() - 1);
  };
  for (std::uint32_t v = 0; v < b.size(); ++v) {
    std::uint32_t up = b.parent[v] == kNone ? kNone : local[b.parent[v]];
    double mass = b.mass[v];
    if (up != kNone) {
      const std::uint32_t u = b.parent[v];
      // Only branches thick enough to be fitted (CentreLineParams::min_hint_spacings).
      const double limit = std::max(edge_radii * b.radius[v], edge_spacings * spacing);
      const int parts = b.radius[v] < min_radius
                            ? 1
                            : int(std::min(64.0, std::ceil((b.pos[v] - b.pos[u]).norm() / limit)));
      // The edge's points are shared among its parts (collapses weight positions by mass).
      mass = b.mass[v] / std::max(parts, 1);
      for (int k = 1; k < parts; ++k) {
        const double t = double(k) / parts;
        up = push(b.pos[u] + t * (b.pos[v] - b.pos[u]), up, kNone, b.weight[v],
                  b.radius[u] + t * (b.radius[v] - b.radius[u]), mass);
      }
    }
    local[v] = push(b.pos[v], up, b.vertex[v], b.weight[v], b.radius[v], mass);
  }
  b = std::move(out);
}

std::size_t drop_branches_inside_stems(Bsg& b, const std::vector<std::uint8_t>& fitted,
                                       double spacing) {
  const std::size_t n = b.size();
  if (n < 3 || fitted.size() != n) return 0;
  // Containers: the edges whose both ends were fitted.
  std::vector<std::uint8_t> container(n, 0);
  for (std::uint32_t v = 0; v < n; ++v) {
    const std::uint32_t u = b.parent[v];
    container[v] = u != kNone && fitted[v] && fitted[u];
  }
  return drop_chains_inside_edges(b, container, std::vector<std::uint8_t>(n, 1), spacing);
}

std::size_t drop_chains_inside_edges(Bsg& b, const std::vector<std::uint8_t>& container,
                                     const std::vector<std::uint8_t>& tip_may_go, double spacing) {
  const std::size_t n = b.size();
  if (n < 3 || container.size() != n || tip_may_go.size() != n) return 0;
  // The container edges as cylinders of the larger radius of their ends.
  std::vector<std::uint32_t> seg;  // child vertex of each container edge
  std::vector<Eigen::Vector3d> mid;
  double reach = 0;
  for (std::uint32_t v = 0; v < n; ++v) {
    const std::uint32_t u = b.parent[v];
    if (u == kNone || !container[v]) continue;
    seg.push_back(v);
    mid.push_back(0.5 * (b.pos[u] + b.pos[v]));
    const double r = std::max(b.radius[u], b.radius[v]);
    reach = std::max(reach, 0.5 * (b.pos[v] - b.pos[u]).norm() + 1.5 * r + 3 * spacing);
  }
  if (seg.empty()) return 0;
  const PointIndex index(mid);
  std::vector<std::uint8_t> alive(n, 1);
  std::vector<int> children(n, 0);
  for (std::uint32_t v = 1; v < n; ++v) {
    if (b.parent[v] != kNone) ++children[b.parent[v]];
  }
  std::vector<std::uint8_t> in_chain(n, 0);
  std::vector<std::uint32_t> chain, near;
  auto inside_other = [&](const Eigen::Vector3d& q) {
    near.clear();
    index.within(q, reach, near);
    for (std::uint32_t k : near) {
      const std::uint32_t v = seg[k], u = b.parent[v];
      if (!alive[v] || in_chain[v]) continue;
      const Eigen::Vector3d a = b.pos[u], ab = b.pos[v] - a;
      const double l2 = ab.squaredNorm();
      const double t = l2 > 0 ? std::clamp((q - a).dot(ab) / l2, 0.0, 1.0) : 0.0;
      const double r = std::max(b.radius[u], b.radius[v]);
      if ((q - a - t * ab).norm() <= 1.1 * r + 2 * spacing) return true;
    }
    return false;
  };
  // A duplicate of a stem that hangs from a neighbouring branch (the shortest paths to the upper
  // trunk of a one-station scan ran through a limb's base and back) crosses from its fork to the
  // stem outside both: up to a quarter of its nodes may lie outside, its tip may not.
  constexpr double kMaxOutsideShare = 0.25;
  std::size_t removed = 0;
  for (int round = 0; round < 4; ++round) {
    std::size_t this_round = 0;
    // Leaf chains, from the tip down to the fork, tips in descending index order (removals take
    // effect at once, so of two chains centred on one axis only one goes).
    for (std::uint32_t tip = std::uint32_t(n); tip-- > 1;) {
      if (!alive[tip] || children[tip] != 0 || !tip_may_go[tip]) continue;
      chain.clear();
      for (std::uint32_t v = tip; v != kNone && b.parent[v] != kNone; v = b.parent[v]) {
        chain.push_back(v);
        if (children[b.parent[v]] != 1) break;
      }
      const std::uint32_t fork = b.parent[chain.back()];
      if (fork == kNone || children[fork] < 2) continue;  // the trunk's own top
      for (std::uint32_t v : chain) in_chain[v] = 1;
      std::size_t outside = 0;
      bool tip_inside = false;
      for (std::uint32_t v : chain) {
        const bool in = inside_other(b.pos[v]);
        outside += !in;
        if (v == tip) tip_inside = in;
      }
      const bool inside = tip_inside && double(outside) <= kMaxOutsideShare * double(chain.size());
      for (std::uint32_t v : chain) in_chain[v] = 0;
      if (!inside) continue;
      for (std::uint32_t v : chain) alive[v] = 0;
      --children[fork];
      this_round += chain.size();
    }
    removed += this_round;
    if (this_round == 0) break;
  }
  if (removed == 0) return 0;
  // Whole leaf chains go, so the survivors' parents survive; indices keep their order.
  Bsg out;
  std::vector<std::uint32_t> local(n, kNone);
  for (std::uint32_t v = 0; v < n; ++v) {
    if (!alive[v]) continue;
    local[v] = std::uint32_t(out.size());
    append_node(out, b, v, b.parent[v] == kNone ? kNone : local[b.parent[v]]);
  }
  b = std::move(out);
  return removed;
}

void smooth_fitted_radii(const std::vector<std::uint32_t>& parent, const CentreLineResult& fit,
                         std::vector<double>& radius) {
  const std::size_t n = parent.size();
  std::vector<std::vector<double>> near(n);
  for (std::uint32_t v = 0; v < n; ++v) {
    if (!fit.fitted[v]) continue;
    near[v].push_back(fit.radius[v]);
    const std::uint32_t u = parent[v];
    if (u < n && fit.fitted[u]) near[v].push_back(fit.radius[u]), near[u].push_back(fit.radius[v]);
  }
  const std::vector<double> prior = radius;  // the caller's (allometric) radii
  for (std::uint32_t v = 0; v < n; ++v) {
    if (!fit.fitted[v]) continue;
    auto& a = near[v];
    std::sort(a.begin(), a.end());
    radius[v] = a.size() % 2 ? a[a.size() / 2] : 0.5 * (a[a.size() / 2 - 1] + a[a.size() / 2]);
  }
  // Nodes without a fit below a fitted one keep the allometric shape, anchored on the nearest
  // fitted ancestor's measured radius (never above it): otherwise a branch alternates between
  // fitted and allometric radii, which may differ by 3 x, and its mesh looks knotted.
  std::vector<std::uint32_t> order, main_child;
  tree_order(parent, order, main_child);
  // A fitted radius more than kMaxRadiusStep times its parent's is not a stem's: the pipe model
  // (Livny et al. 4.3) never lets a child be thicker than its parent, and twice leaves room for
  // fit noise and for a parent fitted small from one side. Circles of several metres fitted to
  // the sparse crown of an airborne scan (adtree_ahn3_delft: 2.7 m after 0.25 m) are such; they
  // take the allometric shape below the last sound radius like the unfitted nodes.
  constexpr double kMaxRadiusStep = 2;
  std::vector<std::uint32_t> anchor(n, kNone);
  for (std::uint32_t v : order) {
    const std::uint32_t u = parent[v] < n ? parent[v] : kNone;
    const bool too_thick = fit.fitted[v] && u != kNone && radius[v] > kMaxRadiusStep * radius[u];
    if (fit.fitted[v] && !too_thick) {
      anchor[v] = v;
      continue;
    }
    anchor[v] = u == kNone ? kNone : anchor[u];
    const std::uint32_t a = anchor[v];
    if (a != kNone && prior[a] > 0) {
      radius[v] = radius[a] * std::min(1.0, prior[v] / prior[a]);
    } else if (too_thick) {
      radius[v] = radius[u];  // no sound radius above it: its parent's
    }
  }
}

std::size_t centre_skeleton(Skeleton& s, const std::vector<Eigen::Vector3d>& points,
                            const CentreLineParams& params) {
  std::vector<Eigen::Vector3d> pos;
  std::vector<std::uint32_t> parent;
  std::vector<double> radius;
  for (const SkeletonNode& node : s.nodes) {
    pos.emplace_back(node.position.x, node.position.y, node.position.z);
    parent.push_back(node.parent == kNoParent ? kNone : node.parent);
    radius.push_back(node.radius);
  }
  const PointIndex index(points);
  const CentreLineResult fit = centre_line(pos, parent, radius, points, index, {}, params);
  smooth_fitted_radii(parent, fit, radius);
  std::vector<Vec3> shift(s.size());
  for (std::size_t v = 0; v < s.size(); ++v) {
    const Vec3 moved{pos[v].x(), pos[v].y(), pos[v].z()};
    shift[v] = moved - s.nodes[v].position;
    s.nodes[v].position = moved;
    s.nodes[v].radius = radius[v];
  }
  for (OrganAnchor& o : s.organs) {
    if (o.node < s.size()) o.position = o.position + shift[o.node];
  }
  return fit.fitted_count;
}

}  // namespace ramus::bsg
