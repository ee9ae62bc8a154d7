// reconstruct(): the order of the stages of Livny et al. 2010 (4.1 -> 4.2 iterated -> 4.3).
#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>

#include "reconstruct/bsg/axis_projection.h"
#include "reconstruct/bsg/bases.h"
#include "reconstruct/bsg/bridge.h"
#include "reconstruct/bsg/centre_line.h"
#include "reconstruct/bsg/chain_order.h"
#include "reconstruct/bsg/coincident_chains.h"
#include "reconstruct/bsg/finite_points.h"
#include "reconstruct/bsg/forest.h"
#include "reconstruct/bsg/fork_placement.h"
#include "reconstruct/bsg/graph.h"
#include "reconstruct/bsg/inflate.h"
#include "reconstruct/bsg/kdtree.h"
#include "reconstruct/bsg/output.h"
#include "reconstruct/bsg/refine.h"
#include "reconstruct/bsg/stem_tracking.h"
#include "reconstruct/bsg/stray_points.h"
#include "reconstruct/bsg/tip_extension.h"
#include "reconstruct/bsg/trunk_radius.h"
#include "reconstruct/reconstruct.h"
#include "reconstruct/wood/reconstruct_wood.h"

namespace ramus {

namespace {

using namespace bsg;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

struct Scale {
  double height, voxel;
};

// `spacing`: the median point spacing when the caller has measured it (< 0: measured here).
Scale choose_scale(const std::vector<Eigen::Vector3d>& pts, const std::vector<std::uint8_t>& keep,
                   const ReconstructOptions& o, double spacing = -1) {
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e300), hi = -lo;
  std::vector<std::uint32_t> ids;
  for (std::uint32_t i = 0; i < pts.size(); ++i) {
    if (!keep[i]) continue;
    lo = lo.cwiseMin(pts[i]), hi = hi.cwiseMax(pts[i]);
    ids.push_back(i);
  }
  const double extent = (hi - lo).maxCoeff();
  Scale s;
  s.height = std::max(hi.z() - lo.z(), 1e-3 * extent);
  if (o.voxel_size > 0) {
    s.voxel = o.voxel_size;
  } else {
    // About one point spacing, so that 1-1.3 cm twigs are not merged with their neighbours
    // (docs/reconstruction.md, Accuracy), but never finer than a fraction of the height. Thick
    // branches are brought to one chain by the thickness-adaptive axis projection below.
    if (spacing < 0) spacing = median_spacing(pts, ids, false);
    s.voxel = std::max(o.voxel_spacings * spacing, s.height * o.voxel_height_floor);
  }
  if (!(s.voxel > 0)) s.voxel = std::max(extent, 1.0) * 1e-3;
  return s;
}

BaseParams base_params(const ReconstructOptions& o, const Scale& s) {
  BaseParams p;
  p.ground_band = o.ground_band > 0 ? o.ground_band : 0.015 * s.height;
  p.cell = o.base_cell > 0 ? o.base_cell : std::max(0.01 * s.height, 1e-9);
  p.slab = o.base_slab > 0 ? o.base_slab : 0.1 * s.height;
  p.max_trunk_width = o.max_trunk_width > 0 ? o.max_trunk_width : 0.3 * s.height;
  p.min_separation = o.min_tree_separation > 0 ? o.min_tree_separation : 0.1 * s.height;
  p.remove_terrain = o.remove_terrain;
  return p;
}

// Graph vertex of every base, without repeats (two bases on one vertex are one tree), and the
// footprint half-width of each (the first base's on a shared vertex). `index` is over g.pos.
std::vector<std::uint32_t> root_vertices(const Graph& g, const PointIndex& index,
                                         const Bases& bases, std::vector<double>& reach) {
  std::vector<std::uint32_t> roots;
  if (g.size() == 0) return roots;
  for (std::size_t b = 0; b < bases.roots.size(); ++b) {
    const std::uint32_t v = index.nearest(bases.roots[b]);
    if (std::find(roots.begin(), roots.end(), v) != roots.end()) continue;
    roots.push_back(v);
    reach.push_back(bases.reach[b]);
  }
  return roots;
}

std::vector<Bsg> refined_trees(const Graph& g, const Forest& f,
                               const std::vector<std::uint32_t>& roots, double own) {
  std::vector<Bsg> trees(roots.size());
  tbb::parallel_for(std::size_t(0), roots.size(), [&](std::size_t t) {
    trees[t] = extract_tree(g, f, std::uint32_t(t), roots);
    refine(trees[t], own);
  });
  return trees;
}

// Centre lines (docs/reconstruction.md): long edges split so that curved stems get cross-sections
// of their own, then nodes onto the fitted axes of the wood and radii from the same fits.
void centre_tree(Bsg& b, const std::vector<Eigen::Vector3d>& samples,
                 const std::vector<std::uint32_t>& counts, const PointIndex& index, double voxel,
                 bool join_coincident) {
  CentreLineParams cp;
  cp.spacing = voxel;
  subdivide_long_edges(b, voxel, cp.min_hint_spacings * voxel);
  const std::vector<double> weight(counts.begin(), counts.end());
  const CentreLineResult fit = centre_line(b.pos, b.parent, b.radius, samples, index, weight, cp);
  smooth_fitted_radii(b.parent, fit, b.radius);
  if (fit.fitted_count == 0) return;
  std::vector<std::uint8_t> fitted = fit.fitted;
  {
    // The trunk followed up the wood from its fitted base; what it passes hangs from it.
    std::uint32_t start = kNone;
    const StemTrack track = track_trunk(b, fitted, index, samples, weight, voxel, start);
    rehang_on_track(b, fitted, track, start, voxel);
  }
  place_forks(b, fitted, voxel);
  drop_branches_inside_stems(b, fitted, voxel);
  return_nodes_behind_forks(b, cp.min_hint_spacings * voxel);
  order_chains_along_axes(b, cp.min_hint_spacings * voxel);
  if (join_coincident) {
    CoincidentChainParams mp;
    mp.spacing = voxel;
    join_coincident_chains(b, mp);
  }
}

}  // namespace

ReconstructResult reconstruct(const PointCloud& cloud, const ReconstructOptions& o) {
  // Foliage first (docs/wood-separation.md): the method assumes wood points.
  if (o.leaves_in_scan != LeafHandling::kKeep) return reconstruct_without_leaves(cloud, o);
  const auto start = Clock::now();
  ReconstructResult res;
  FinitePoints finite_points = read_finite_points(cloud, res);
  std::vector<Eigen::Vector3d>& pts = finite_points.pts;
  std::vector<std::uint8_t>& keep = finite_points.keep;
  if (finite_points.coincide()) {
    res.notes.push_back("all points coincide: no tree");
    res.timings.total = seconds_since(start);
    return res;
  }
  // The height sets the base-finding scales; the voxel is chosen after terrain removal, so a
  // sparse ground does not coarsen the grid of the trees.
  ReconstructOptions height_only = o;
  height_only.voxel_size = 1.0;
  Scale scale = choose_scale(pts, keep, height_only);

  // 4.1: tree bases and terrain.
  auto t = Clock::now();
  // Stray points (StrayPasses): alone in the air now, small clusters after the terrain. The voxel
  // of the whole cloud sets the reach (the trees' own is chosen after terrain removal, below).
  StrayRule rule;
  rule.min_cluster = o.stray_cluster;
  StrayPasses stray(rule);
  if (o.remove_stray) {
    stray.alone(pts, keep,
                [&](double spacing) { return 4 * choose_scale(pts, keep, o, spacing).voxel; });
  }
  Bases bases;
  if (o.roots.empty()) {
    bases = find_bases(pts, keep, base_params(o, scale));
  } else {
    bases.terrain.assign(pts.size(), 0);
    for (const Vec3& r : o.roots) {
      const Vec3 rel = r - cloud.offset;
      bases.roots.emplace_back(rel.x, rel.y, rel.z);
      bases.reach.push_back(0.5 * base_params(o, scale).max_trunk_width);
    }
  }
  for (std::size_t i = 0; i < pts.size(); ++i) {
    if (bases.terrain[i]) keep[i] = 0, ++res.counts.terrain_points;
  }
  if (!bases.roots.empty()) stray.clusters(pts, keep);
  res.counts.stray_points = stray.dropped();
  if (stray.dropped() > 0) res.notes.push_back(stray.note("voxels"));
  if (res.counts.terrain_points + res.counts.stray_points < finite_points.count) {
    scale.voxel = choose_scale(pts, keep, o).voxel;
    res.voxel_size = scale.voxel;
  }
  res.timings.bases = seconds_since(t);
  if (bases.roots.empty()) {
    res.notes.push_back(bases.note);
    res.timings.total = seconds_since(start);
    return res;
  }

  // 4.1: the neighbourhood graph on voxel-merged points, gaps bridged.
  t = Clock::now();
  std::vector<std::uint32_t> point_vertex;
  Graph graph = voxelize(pts, keep, scale.voxel, point_vertex);
  std::vector<double> root_reach;
  std::vector<std::uint32_t> roots;
  {
    // One k-d tree over the voxel vertices for the neighbours and the roots.
    const PointIndex index(graph.pos);
    link_nearest(graph, std::max(1, o.neighbours), index);
    roots = root_vertices(graph, index, bases, root_reach);
  }
  const double max_gap = o.max_gap > 0 ? o.max_gap : std::max(0.08 * scale.height, 3 * scale.voxel);
  const std::vector<Eigen::Vector3d> sample_pos = graph.pos;
  if (o.axis_levels > 0) {
    AxisProjectionParams ap;
    ap.levels = o.axis_levels;
    ap.linearity = o.axis_linearity;
    ap.passes = o.axis_passes;
    project_to_axes(graph, scale.voxel, ap);
  }
  // Gaps are bridged between the projected samples: a gap is then measured between branch axes,
  // so the continuation of a fragment's own branch is nearer than the bark of a neighbouring one
  // (docs/reconstruction.md, The pipeline, step 3).
  // A hidden limb (seen only beyond the stem it leaves) may reach farther (3 x by default) once
  // nothing else can be bridged, when it is at least as long as the shortest twig kept (10
  // voxels, below).
  BridgeParams bridge;
  bridge.max_gap = max_gap;
  bridge.hidden_limb_gap = o.hidden_limb_reach * max_gap;
  bridge.hidden_limb_length = 10 * scale.voxel;
  res.counts.bridged_gaps = bridge_gaps(graph, roots, bridge);
  contract(graph, std::max(0, o.contraction_steps));
  res.counts.graph_vertices = graph.size();
  res.counts.graph_edges = graph.edge_count();
  res.timings.graph = seconds_since(t);
  if (roots.empty()) {
    res.notes.push_back("no points remain after terrain removal");
    res.timings.total = seconds_since(start);
    return res;
  }

  // 4.1 + 4.2: Dijkstra forest, refinement, reweighting, until the forest stops changing.
  const double own = scale.voxel;
  Forest forest;
  std::vector<Bsg> trees;
  Graph weighted = graph;
  const PointIndex graph_index(graph.pos);  // graph.pos does not change from here on
  for (int it = 0; it < std::max(1, o.max_iterations); ++it) {
    t = Clock::now();
    Forest next = shortest_path_forest(weighted, roots);
    res.timings.forest += seconds_since(t);
    const bool settled = it > 0 && forest_change(forest, next) < o.convergence;
    forest = std::move(next);
    t = Clock::now();
    trees = refined_trees(graph, forest, roots, own);
    res.counts.iterations = it + 1;
    if (settled || it + 1 == o.max_iterations) {
      res.timings.refine += seconds_since(t);
      break;
    }
    weighted = reweighted(graph, graph_index, trees, o.reweight_strength, 3 * scale.voxel);
    res.timings.refine += seconds_since(t);
  }

  // 4.3: inflation and clustering, one tree per task.
  t = Clock::now();
  std::vector<std::vector<Eigen::Vector3d>> samples(roots.size());
  std::vector<std::vector<std::uint32_t>> counts(roots.size());
  for (std::uint32_t v = 0; v < graph.size(); ++v) {
    if (forest.tree[v] == kNone) continue;
    samples[forest.tree[v]].push_back(sample_pos[v]);
    counts[forest.tree[v]].push_back(graph.points[v]);
  }
  InflateParams ip;
  ip.exponent = o.allometry_exponent;
  ip.overlap = o.overlap_fraction;
  ip.own_weight = own;
  ip.edge_sample = scale.voxel;
  ip.tolerance = 0.5 * scale.voxel;
  // Ten voxels (the point spacing sets what the scan supports, issue 19). The former floor of 2%
  // of the height, there against the spurs bark noise grows on thin whips, also cut real twigs
  // of 20-25 cm on a 13 m tree; since the centre lines take the spurs that lie along stems, the
  // floor costs more recall (broadleaf, three stations: 0.872 against 0.911) than it saves.
  ip.min_twig = o.min_branch_length > 0 ? o.min_branch_length : 10 * scale.voxel;
  ip.min_radius = o.min_cylinder_radius > 0 ? o.min_cylinder_radius : 2 * scale.voxel;
  const BaseParams bp = base_params(o, scale);
  std::vector<Skeleton> skeletons(roots.size());
  tbb::parallel_for(std::size_t(0), roots.size(), [&](std::size_t k) {
    if (trees[k].size() < 2) return;
    InflateParams tp = ip;
    // The circles are fitted in the lower half of the base slab, within the trunk's footprint
    // (trunk_radius.h: robust fits in shrinking windows, so that a conifer's skirt of branches
    // and the ground around the base do not widen them).
    tp.root_radius = trunk_radius(samples[k], graph.pos[roots[k]], 0.5 * bp.slab, 2 * root_reach[k],
                                  scale.voxel);
    inflate(trees[k], samples[k], counts[k], tp);
    if (o.centre_lines || o.extend_tips) {
      const PointIndex index(samples[k]);  // both steps search the tree's samples
      if (o.centre_lines)
        centre_tree(trees[k], samples[k], counts[k], index, scale.voxel, o.join_coincident);
      if (o.extend_tips) {
        TipExtensionParams xp;
        xp.spacing = scale.voxel;
        extend_tips(trees[k], samples[k], index, xp);
      }
    }
    LeafParams lp{o.leaves,     o.min_leaves,
                  o.max_leaves, o.leaf_sphere > 0 ? o.leaf_sphere : 2 * scale.voxel,
                  o.seed,       k};
    skeletons[k] = to_skeleton(trees[k], cloud.offset, lp);
  });
  res.timings.inflate = seconds_since(t);

  // Trees keep their base's index in point_tree only when they produced a skeleton.
  std::vector<std::uint32_t> renumber(roots.size(), ReconstructResult::kNoTree);
  for (std::size_t k = 0; k < roots.size(); ++k) {
    if (skeletons[k].size() < 2) continue;
    renumber[k] = std::uint32_t(res.trees.size());
    res.counts.skeleton_nodes += skeletons[k].size();
    res.trees.push_back(std::move(skeletons[k]));
  }
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const std::uint32_t v = point_vertex[i];
    if (v == kNone) continue;
    if (forest.tree[v] == kNone) {
      ++res.counts.unreached_points;
    } else {
      res.point_tree[i] = renumber[forest.tree[v]];
    }
  }
  if (res.trees.empty()) res.notes.push_back("no tree base grew into a skeleton");
  res.timings.total = seconds_since(start);
  return res;
}

}  // namespace ramus
