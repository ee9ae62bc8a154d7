// flood_reconstruct(): tree bases, voxelization (Alg. 2), and the breadth-first growth of every
// tree by flooding (Alg. 3), direction splitting and line fitting (Alg. 4), radii (Alg. 5).
#include "reconstruct/flood/flood_skeleton.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <deque>

#include "reconstruct/bsg/bases.h"
#include "reconstruct/bsg/centre_line.h"
#include "reconstruct/bsg/finite_points.h"
#include "reconstruct/bsg/kdtree.h"
#include "reconstruct/bsg/stray_points.h"
#include "reconstruct/flood/line_fit.h"
#include "reconstruct/flood/voxel_grid.h"

namespace ramus::flood {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

Eigen::Vector3d to_eigen(const Vec3& v) { return {v.x, v.y, v.z}; }
Vec3 from_eigen(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }

// An orthonormal turtle frame with the given heading (H x L = U).
void set_frame(SkeletonNode& n, const Vec3& heading) {
  n.heading = normalized(heading);
  const Vec3 ref = std::abs(n.heading.z) < 0.9 ? Vec3{0, 0, 1} : Vec3{1, 0, 0};
  n.left = normalized(cross(ref, n.heading));
  n.up = cross(n.heading, n.left);
}

// Median distance to the nearest other kept point (bsg::median_spacing over the kept ones).
double median_spacing(const std::vector<Eigen::Vector3d>& pts,
                      const std::vector<std::uint8_t>& keep) {
  std::vector<std::uint32_t> ids;
  for (std::uint32_t i = 0; i < pts.size(); ++i) {
    if (keep[i]) ids.push_back(i);
  }
  return bsg::median_spacing(pts, ids, false);
}

// One node waiting to grow: its tree, its index there, and the voxels its flood starts from.
struct Pending {
  std::uint32_t tree, node;
  std::vector<std::uint32_t> seed;
  bool lateral = false;  // a side branch leaving the node (its children are one order higher)
};

// The growth state shared by all trees of the scan.
class Grower {
 public:
  Grower(const std::vector<Vec3>& pts, const VoxelGrid& grid, const FloodOptions& o)
      : pts_(pts), grid_(grid), o_(o), consumed_(grid.size(), 0), label_(grid.size(), kNone) {}

  bool consumed(std::uint32_t v) const { return consumed_[v] != 0; }
  // The tree whose flood reached voxel v, or kNone.
  std::uint32_t owner(std::uint32_t v) const { return consumed_[v] ? consumed_[v] - 1 : kNone; }
  static constexpr std::uint32_t kNone = 0xffffffffu;

  // Grows one node: floods from its seed, splits the last layer into directions and appends one
  // child per direction to `tree` (relative coordinates), queueing them.
  void grow(Pending p, std::vector<Skeleton>& trees, std::deque<Pending>& queue) {
    Skeleton& tree = trees[p.tree];
    const Vec3 x0 = tree.nodes[p.node].position;
    flood(p.seed, p.tree + 1);
    std::vector<Direction> dirs = split(x0);
    // A last layer much smaller than the cross-section the flood started from is the corner of a
    // branch's end, not a continuation: the branch ends here.
    std::size_t frontier = 0;
    for (const Direction& d : dirs) frontier += d.frontier.size();
    if (double(frontier) < o_.end_fraction * double(p.seed.size())) dirs.clear();
    if (dirs.empty()) {
      add_tip(tree, p, x0);
    } else {
      add_children(tree, p, x0, dirs, queue);
    }
  }

 private:
  struct Direction {
    std::vector<std::uint32_t> frontier;  // voxels of the last flood layer in this direction
    std::vector<Vec3> points;             // all points of the neighbourhood assigned to it
    Vec3 frontier_centre{0, 0, 0};
    double spread = 0;    // largest distance of a frontier point from frontier_centre
    bool sparse = false;  // too few points for a child of its own here
  };

  // Alg. 3: layer-by-layer flood through the 26 neighbours of the neighbourhood S (voxels_), each
  // reached voxel consumed at once. The flood stops when a layer adds at most lambda x |S| voxels
  // (the growth ratio mu of line 10), or nothing at all (the branch ends inside S).
  void flood(const std::vector<std::uint32_t>& seed, std::uint32_t owner) {
    voxels_.clear();
    pred_.clear();
    layer_begin_ = 0;
    ended_ = false;
    for (std::uint32_t v : seed) {
      consumed_[v] = owner;
      voxels_.push_back(v);
      pred_.push_back(kNone);
    }
    std::size_t begin = 0, end = voxels_.size();
    for (int layer = 0; layer < o_.max_layers; ++layer) {
      for (std::size_t k = begin; k < end; ++k) {
        for (int dz = -1; dz <= 1; ++dz) {
          for (int dy = -1; dy <= 1; ++dy) {
            for (int dx = -1; dx <= 1; ++dx) {
              if (!dx && !dy && !dz) continue;
              const std::uint32_t w = grid_.neighbour(voxels_[k], dx, dy, dz);
              if (w == kNoVoxel || consumed_[w]) continue;
              consumed_[w] = owner;
              voxels_.push_back(w);
              pred_.push_back(std::uint32_t(k));
            }
          }
        }
      }
      const std::size_t added = voxels_.size() - end;
      if (added == 0) {
        ended_ = true;
        break;
      }
      const double mu = double(added) / double(end);  // line 10: |S'| / |S|
      begin = end;
      end = voxels_.size();
      layer_begin_ = begin;
      if (!(mu > o_.growth_ratio)) break;  // line 11
    }
    if (layer_begin_ == 0 && !ended_) layer_begin_ = voxels_.size();  // max_layers == 0
  }

  // Alg. 4 input: the last layer's 26-connected groups are the directions D; every voxel of S
  // follows its flood path to the group it leads to (voxels whose path ends inside S join the
  // group nearest in angle). Directions with too few points are dropped (section 4.2.3).
  std::vector<Direction> split(const Vec3& x0) {
    std::vector<Direction> dirs;
    if (ended_) return dirs;
    const std::size_t n = voxels_.size();
    std::vector<std::uint32_t> local(n, kNone);
    for (std::size_t k = layer_begin_; k < n; ++k) label_[voxels_[k]] = std::uint32_t(k);
    // Connected groups of the last layer by flood through it (label_ maps voxel -> slot). Bark
    // scans are hollow: the layer is a ring with gaps where the sampling is sparse, so voxels up
    // to `frontier_link` cells apart count as connected (1: the 26 neighbours).
    const int link = std::max(1, o_.frontier_link);
    for (std::size_t k = layer_begin_; k < n; ++k) {
      if (local[k] != kNone) continue;
      const auto g = std::uint32_t(dirs.size());
      dirs.emplace_back();
      std::vector<std::uint32_t> stack{std::uint32_t(k)};
      local[k] = g;
      while (!stack.empty()) {
        const std::uint32_t s = stack.back();
        stack.pop_back();
        dirs[g].frontier.push_back(voxels_[s]);
        for (int dz = -link; dz <= link; ++dz) {
          for (int dy = -link; dy <= link; ++dy) {
            for (int dx = -link; dx <= link; ++dx) {
              const std::uint32_t w = grid_.neighbour(voxels_[s], dx, dy, dz);
              if (w == kNoVoxel || label_[w] == kNone || local[label_[w]] != kNone) continue;
              local[label_[w]] = g;
              stack.push_back(label_[w]);
            }
          }
        }
      }
    }
    for (std::size_t k = layer_begin_; k < n; ++k) label_[voxels_[k]] = kNone;
    centre_groups(dirs, x0);
    merge_arcs(dirs, local, x0);
    // Back along the flood paths: a voxel belongs to the first group one of its successors does.
    for (std::size_t k = n; k-- > 0;) {
      if (local[k] != kNone && pred_[k] != kNone && local[pred_[k]] == kNone) {
        local[pred_[k]] = local[k];
      }
    }
    std::size_t total = 0;
    for (std::size_t k = 0; k < n; ++k) {
      std::uint32_t g = local[k];
      const std::uint32_t v = voxels_[k];
      if (g == kNone) {
        // A dead end inside the neighbourhood (a twig shorter than one step).
        const Vec3 u = normalized(pts_[*grid_.begin(v)] - x0);
        double best = -2;
        for (std::uint32_t j = 0; j < dirs.size(); ++j) {
          const double c = dot(u, normalized(dirs[j].frontier_centre - x0));
          if (c > best) best = c, g = j;
        }
      }
      for (const std::uint32_t* q = grid_.begin(v); q != grid_.end(v); ++q) {
        dirs[g].points.push_back(pts_[*q]);
      }
      total += grid_.count(v);
    }
    // Sparse directions go (the largest one always stays, so a branch never stops here).
    std::stable_sort(dirs.begin(), dirs.end(), [](const Direction& a, const Direction& b) {
      return a.points.size() > b.points.size();
    });
    const double keep_at =
        std::max(double(o_.min_direction_points), o_.min_direction_fraction * double(total));
    for (std::size_t k = 1; k < dirs.size(); ++k) {
      dirs[k].sparse = double(dirs[k].points.size()) < keep_at;
    }
    return dirs;
  }

  // Centre and spread (largest distance of a point from the centre) of every group's points.
  void centre_groups(std::vector<Direction>& dirs, const Vec3& x0) const {
    for (Direction& d : dirs) {
      Vec3 c{0, 0, 0};
      std::size_t m = 0;
      for (std::uint32_t v : d.frontier) {
        for (const std::uint32_t* q = grid_.begin(v); q != grid_.end(v); ++q) c += pts_[*q], ++m;
      }
      d.frontier_centre = m ? c / double(m) : x0;
      d.spread = 0;
      for (std::uint32_t v : d.frontier) {
        for (const std::uint32_t* q = grid_.begin(v); q != grid_.end(v); ++q) {
          d.spread = std::max(d.spread, distance(pts_[*q], d.frontier_centre));
        }
      }
    }
  }

  // On a hollow (bark-only) branch the last layer can be a ring broken into arcs. Arcs of one
  // ring have centres closer than their own spread (two half rings of radius r: 1.27 r apart,
  // spread 1.19 r); the cross-sections of two branches leaving a fork are at least their radii
  // apart (2 r, spread r). Groups closer than 1.5 x the larger spread are one direction.
  void merge_arcs(std::vector<Direction>& dirs, std::vector<std::uint32_t>& local,
                  const Vec3& x0) const {
    bool merged = true;
    while (merged && dirs.size() > 1) {
      merged = false;
      for (std::size_t i = 0; i < dirs.size() && !merged; ++i) {
        for (std::size_t j = i + 1; j < dirs.size() && !merged; ++j) {
          const double gap = distance(dirs[i].frontier_centre, dirs[j].frontier_centre);
          if (!(gap < 1.5 * std::max(dirs[i].spread, dirs[j].spread))) continue;
          dirs[i].frontier.insert(dirs[i].frontier.end(), dirs[j].frontier.begin(),
                                  dirs[j].frontier.end());
          dirs.erase(dirs.begin() + std::ptrdiff_t(j));
          for (std::uint32_t& g : local) {
            if (g == kNone) continue;
            if (g == j) {
              g = std::uint32_t(i);
            } else if (g > j) {
              --g;
            }
          }
          centre_groups(dirs, x0);
          merged = true;
        }
      }
    }
  }

  // Alg. 4 lines 1-4 with Alg. 5: one child per direction. The least-squares line through the
  // current node gives the branch's direction (the child's heading) and its radius. The child
  // lies at the centre of the direction's last layer, i.e. on the branch's cross-section where
  // the step ends: the end of the line itself would put the child on the far side of the axis
  // whenever the current node is off it (the line through x0 aims at the points' centroid
  // half-way), and the skeleton would zig-zag. The largest direction continues the parent's
  // axis (same order); the others are lateral branches.
  void add_children(Skeleton& tree, const Pending& p, const Vec3& x0, std::vector<Direction>& dirs,
                    std::deque<Pending>& queue) {
    for (std::size_t k = 0; k < dirs.size(); ++k) {
      Direction& d = dirs[k];
      if (d.sparse) {
        // No child from a sparse direction (section 4.2.3: no stray twigs at every node), but
        // its flood goes on from the same node: a thin branch leaving a thick one becomes a
        // child once it has grown out of the parent's neighbourhood, a stray twig never does.
        queue.push_back({p.tree, p.node, std::move(d.frontier), true});
        continue;
      }
      const Vec3 towards = d.frontier_centre - x0;
      const Vec3 start = normalized(towards, tree.nodes[p.node].heading);
      Vec3 dir = fit_line_through(x0, d.points, start).direction;
      // A step shorter than the branch is thick scatters its points more across than along
      // the axis; the line then lies across the branch. The frontier's direction is kept then.
      if (dot(dir, start) < std::cos(M_PI / 4)) dir = start;
      if (!(length(towards) > 0.25 * grid_.edge())) continue;
      SkeletonNode c;
      c.position = d.frontier_centre;
      c.radius = line_radius(x0, dir, d.points, o_.radius_factor);
      c.parent = p.node;
      c.order = std::uint16_t(tree.nodes[p.node].order + (k == 0 && !p.lateral ? 0 : 1));
      set_frame(c, dir);
      const std::uint32_t id = tree.add(c);
      if (tree.nodes[p.node].parent == kNoParent && k == 0) tree.nodes[p.node].radius = c.radius;
      queue.push_back({p.tree, id, std::move(d.frontier)});
    }
  }

  // The branch ends inside the neighbourhood: one last segment along the line fitted to all its
  // points, to the farthest projection.
  void add_tip(Skeleton& tree, const Pending& p, const Vec3& x0) {
    const std::uint32_t node = p.node;
    std::vector<Vec3> points;
    Vec3 c{0, 0, 0};
    for (std::uint32_t v : voxels_) {
      for (const std::uint32_t* q = grid_.begin(v); q != grid_.end(v); ++q) {
        points.push_back(pts_[*q]);
        c += pts_[*q];
      }
    }
    if (points.empty()) return;
    c = c / double(points.size());
    // Near the end the points are mostly the cross-section the flood started from, which lies
    // across the branch; the last segment keeps within 45 degrees of the branch's heading.
    const Vec3 heading = tree.nodes[node].heading;
    Vec3 dir = fit_line_through(x0, points, normalized(c - x0, heading)).direction;
    if (dot(dir, heading) < std::cos(M_PI / 4)) dir = heading;
    double t = 0;
    for (const Vec3& q : points) t = std::max(t, dot(q - x0, dir));
    if (!(t > o_.min_tip_voxels * grid_.edge())) return;
    SkeletonNode n;
    n.position = x0 + dir * t;
    n.radius = line_radius(x0, dir, points, o_.radius_factor);
    n.parent = node;
    n.order = std::uint16_t(tree.nodes[node].order + (p.lateral ? 1 : 0));
    set_frame(n, dir);
    tree.add(n);
    if (tree.nodes[node].parent == kNoParent) tree.nodes[node].radius = n.radius;
  }

  const std::vector<Vec3>& pts_;
  const VoxelGrid& grid_;
  const FloodOptions& o_;
  std::vector<std::uint32_t> consumed_;  // 0, or 1 + the tree that flooded the voxel
  std::vector<std::uint32_t> label_;     // scratch: voxel -> slot in voxels_ for the last layer
  std::vector<std::uint32_t> voxels_, pred_;
  std::size_t layer_begin_ = 0;
  bool ended_ = false;
};

// Scans have gaps (occlusion, thin twigs below the sampling density) that no flood crosses. Each
// group of voxels no flood reached joins the tree node nearest to it, when that node is within
// `max_gap` (plus its radius): the group is flooded from its voxel nearest to the node, as a side
// branch of it. A group whose points span at least `long_group` (bounding-box diagonal) may join
// from up to `long_gap` instead (hidden limbs; the caller passes 0 but in the round after no group
// could join). Returns how many groups were joined; growth then resumes.
std::size_t bridge_gaps(const VoxelGrid& grid, const std::vector<Vec3>& pts, const Grower& grower,
                        const std::vector<Skeleton>& trees, double max_gap, double long_gap,
                        double long_group, std::deque<Pending>& queue) {
  std::vector<Eigen::Vector3d> node_pos;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> node_id;  // (tree, node)
  for (std::uint32_t k = 0; k < trees.size(); ++k) {
    for (std::uint32_t v = 0; v < trees[k].size(); ++v) {
      node_pos.push_back(to_eigen(trees[k].nodes[v].position));
      node_id.emplace_back(k, v);
    }
  }
  if (node_pos.empty()) return 0;
  const bsg::PointIndex nodes(node_pos);
  std::vector<std::uint8_t> seen(grid.size(), 0);
  std::size_t joined = 0;
  for (std::uint32_t start = 0; start < grid.size(); ++start) {
    if (seen[start] || grower.consumed(start)) continue;
    // One 26-connected group of unreached voxels; remember its voxel nearest to a node.
    double best = 1e300;
    std::uint32_t best_voxel = kNoVoxel, best_node = 0;
    Eigen::AlignedBox3d box;
    std::vector<std::uint32_t> stack{start};
    seen[start] = 1;
    while (!stack.empty()) {
      const std::uint32_t v = stack.back();
      stack.pop_back();
      double d2 = 0;
      box.extend(to_eigen(pts[*grid.begin(v)]));
      const std::uint32_t n = nodes.nearest(to_eigen(pts[*grid.begin(v)]), &d2);
      if (d2 < best) best = d2, best_voxel = v, best_node = n;
      for (int dz = -1; dz <= 1; ++dz) {
        for (int dy = -1; dy <= 1; ++dy) {
          for (int dx = -1; dx <= 1; ++dx) {
            const std::uint32_t w = grid.neighbour(v, dx, dy, dz);
            if (w == kNoVoxel || seen[w] || grower.consumed(w)) continue;
            seen[w] = 1;
            stack.push_back(w);
          }
        }
      }
    }
    const auto [tree, node] = node_id[best_node];
    const double reach =
        long_gap > max_gap && box.diagonal().norm() >= long_group ? long_gap : max_gap;
    if (std::sqrt(best) > reach + trees[tree].nodes[node].radius) continue;
    queue.push_back({tree, node, {best_voxel}, true});
    ++joined;
  }
  return joined;
}

}  // namespace

ReconstructResult flood_reconstruct(const PointCloud& cloud, const FloodOptions& o) {
  const auto start = Clock::now();
  ReconstructResult res;
  if (!(o.growth_ratio >= 0) || !(o.radius_factor > 0) || o.dimension < 1 || !(o.voxel_size >= 0) ||
      !std::isfinite(o.voxel_size)) {
    throw ReconstructError(
        "invalid flood options (growth ratio >= 0, radius factor > 0, "
        "dimension >= 1, voxel size >= 0)");
  }
  bsg::FinitePoints finite_points = bsg::read_finite_points(cloud, res);
  const std::vector<Eigen::Vector3d>& epts = finite_points.pts;
  std::vector<std::uint8_t>& keep = finite_points.keep;
  const std::size_t finite = finite_points.count;
  std::vector<Vec3> pts(cloud.size());
  for (std::size_t i = 0; i < cloud.size(); ++i) pts[i] = Vec3(cloud.positions[i]);
  const Vec3 lo{finite_points.lo.x(), finite_points.lo.y(), finite_points.lo.z()};
  const Vec3 hi{finite_points.hi.x(), finite_points.hi.y(), finite_points.hi.z()};
  const double extent = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z});
  if (finite_points.coincide()) {
    res.notes.push_back("all points coincide: no tree");
    res.timings.total = seconds_since(start);
    return res;
  }
  const double height = std::max(hi.z - lo.z, 1e-3 * extent);
  // Mixed-pixel returns (docs/reconstruction.md, Stray points): the flood takes each into its
  // tree's layers and grows a branch to it. The BSG pipeline's two passes (bsg::StrayPasses).
  bsg::StrayRule rule;
  rule.min_cluster = o.stray_cluster;
  bsg::StrayPasses stray(rule);
  if (o.remove_stray)
    stray.alone(epts, keep, [&](double spacing) { return 4 * std::max(spacing, 1e-3 * height); });

  // Tree bases and terrain, with the BSG pipeline's default scales (Livny et al. 4.1).
  auto t = Clock::now();
  bsg::Bases bases;
  if (o.roots.empty()) {
    bsg::BaseParams bp;
    bp.ground_band = 0.015 * height;
    bp.cell = std::max(0.01 * height, 1e-9);
    bp.slab = 0.1 * height;
    bp.max_trunk_width = 0.3 * height;
    bp.min_separation = 0.1 * height;
    bp.remove_terrain = o.remove_terrain;
    bases = bsg::find_bases(epts, keep, bp);
  } else {
    bases.terrain.assign(pts.size(), 0);
    for (const Vec3& r : o.roots) bases.roots.push_back(to_eigen(r - cloud.offset));
  }
  for (std::size_t i = 0; i < pts.size(); ++i) {
    if (bases.terrain[i] && keep[i]) keep[i] = 0, ++res.counts.terrain_points;
  }
  if (!bases.roots.empty()) stray.clusters(epts, keep);
  res.counts.stray_points = stray.dropped();
  if (stray.dropped() > 0) res.notes.push_back(stray.note("point spacings"));
  res.timings.bases = seconds_since(t);
  if (bases.roots.empty()) {
    res.notes.push_back(bases.note.empty() ? "no tree base found" : bases.note);
    res.timings.total = seconds_since(start);
    return res;
  }
  if (res.counts.terrain_points + res.counts.stray_points == finite) {
    res.notes.push_back("no points remain after terrain removal");
    res.timings.total = seconds_since(start);
    return res;
  }

  // Alg. 2: voxelization. The edge follows the dimension d, but never below two point spacings,
  // so that the flood can cross the gaps between the samples of one branch.
  t = Clock::now();
  double edge = o.voxel_size;
  if (!(edge > 0)) edge = std::max(extent / o.dimension, 2.0 * median_spacing(epts, keep));
  if (!(edge > 0)) edge = extent / o.dimension;
  res.voxel_size = edge;
  const VoxelGrid grid(pts, keep, edge);
  res.counts.graph_vertices = grid.size();
  res.timings.graph = seconds_since(t);

  // Breadth-first growth of all trees from their root voxels through one queue.
  t = Clock::now();
  std::vector<std::uint32_t> kept_ids;
  for (std::uint32_t i = 0; i < pts.size(); ++i) {
    if (keep[i]) kept_ids.push_back(i);
  }
  const bsg::PointIndex index(epts, kept_ids);
  Grower grower(pts, grid, o);
  std::vector<Skeleton> trees;
  std::deque<Pending> queue;
  for (const Eigen::Vector3d& b : bases.roots) {
    const std::uint32_t nearest = index.nearest(b);
    const std::uint32_t v = grid.voxel_of_point(nearest);
    if (v == kNoVoxel || grower.consumed(v)) continue;
    bool taken = false;
    for (const Pending& q : queue) taken |= q.seed.front() == v;
    if (taken) continue;
    Skeleton s;
    SkeletonNode root;
    root.position = from_eigen(b);
    s.add(root);
    trees.push_back(std::move(s));
    queue.push_back({std::uint32_t(trees.size() - 1), 0, {v}});
  }
  const double max_gap = o.max_gap > 0 ? o.max_gap : std::max(0.08 * height, 3 * edge);
  // Hidden limbs (FloodOptions::hidden_limb_reach) are tried once no other group can join; after
  // they have grown, the usual gaps first again. Their least size, 10 point spacings, is measured
  // only when they are tried (most scans leave no group unreached).
  double long_group = 0;
  bool hidden = false;
  for (;;) {
    while (!queue.empty()) {
      Pending p = std::move(queue.front());
      queue.pop_front();
      grower.grow(std::move(p), trees, queue);
    }
    const std::size_t bridged =
        bridge_gaps(grid, pts, grower, trees, max_gap, hidden ? o.hidden_limb_reach * max_gap : 0.0,
                    long_group, queue);
    if (bridged == 0) {
      if (hidden || !(o.hidden_limb_reach > 1)) break;
      if (!(long_group > 0)) {
        const double spacing = median_spacing(epts, keep);
        long_group = 10 * (spacing > 0 ? spacing : 0.5 * edge);
      }
      hidden = true;
      continue;
    }
    hidden = false;
    res.counts.bridged_gaps += bridged;
  }
  res.timings.forest = seconds_since(t);

  // Centre lines (docs/reconstruction.md): the flood's nodes sit at the centres of flood layers,
  // which on a bark-only scan of a thick stem are arcs of its surface, not its axis.
  if (o.centre_lines && !trees.empty()) {
    t = Clock::now();
    std::vector<Eigen::Vector3d> wood;
    for (std::uint32_t i : kept_ids) wood.push_back(epts[i]);
    bsg::CentreLineParams cp;
    cp.spacing = 0.5 * edge;
    cp.passes = 1;            // the flood's nodes already sit inside their branches' cross-sections
    cp.centre_roots = false;  // its roots are the bases themselves, not vertices on the bark
    for (Skeleton& s : trees) {
      if (s.size() >= 2) bsg::centre_skeleton(s, wood, cp);
    }
    res.timings.inflate = seconds_since(t);
  }

  // World coordinates; root frames along their first segment. Trees without a segment go.
  std::vector<std::uint32_t> renumber(trees.size(), ReconstructResult::kNoTree);
  for (std::size_t k = 0; k < trees.size(); ++k) {
    Skeleton& s = trees[k];
    if (s.size() < 2) continue;
    set_frame(s.nodes[0], s.nodes[1].position - s.nodes[0].position);
    for (SkeletonNode& n : s.nodes) n.position = cloud.offset + n.position;
    renumber[k] = std::uint32_t(res.trees.size());
    res.counts.skeleton_nodes += s.size();
    res.trees.push_back(std::move(s));
  }
  for (std::uint32_t i = 0; i < pts.size(); ++i) {
    const std::uint32_t v = keep[i] ? grid.voxel_of_point(i) : kNoVoxel;
    if (v == kNoVoxel) continue;
    const std::uint32_t tree = grower.owner(v);
    if (tree == Grower::kNone) {
      ++res.counts.unreached_points;
    } else {
      res.point_tree[i] = renumber[tree];
    }
  }
  if (res.trees.empty()) res.notes.push_back("no tree base grew into a skeleton");
  res.timings.total = seconds_since(start);
  return res;
}

}  // namespace ramus::flood
