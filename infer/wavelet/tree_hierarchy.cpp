// Coarse-to-fine trees of the dyads joined into one tree per level (tree_hierarchy.h).
#include "infer/wavelet/tree_hierarchy.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <unordered_map>

#include "infer/shape/trunk_lean.h"
#include "infer/wavelet/cell_centroids.h"
#include "infer/wavelet/emst.h"

namespace ramus::wavelet {
namespace {

std::uint64_t key(const std::array<int, 3>& c) {
  return std::uint64_t(std::uint32_t(c[0])) | (std::uint64_t(std::uint32_t(c[1])) << 21) |
         (std::uint64_t(std::uint32_t(c[2])) << 42);
}

std::array<int, 3> local_cell(const DyadTree& d, std::size_t i) {
  std::array<int, 3> c;
  for (int k = 0; k < 3; ++k) c[k] = d.cells[i][k] - int(d.block.offset[k]);
  return c;
}

double dist2(const Vec3& d) { return dot(d, d); }

// The coarse node nearest to p (ties: the smaller index), leaving out the base when any other
// node exists: the base is a point on the ground, not wood a finer cell could refine.
std::uint32_t nearest_node(const LevelTree& coarse, const Vec3& p) {
  std::uint32_t best = 0;
  double best_d = std::numeric_limits<double>::infinity();
  const std::uint32_t first = coarse.nodes.size() > 1 ? 1 : 0;
  for (std::uint32_t u = first; u < coarse.nodes.size(); ++u) {
    const double d = dist2(coarse.nodes[u].position - p);
    if (d < best_d) {
      best_d = d;
      best = u;
    }
  }
  return best;
}

// Breadth-first order from the base (node 0) over `parent` links.
std::vector<std::uint32_t> breadth_first(const LevelTree& t) {
  std::vector<std::uint32_t> order{0};
  for (std::size_t k = 0; k < order.size(); ++k) {
    for (std::uint32_t v : t.children[order[k]]) order.push_back(v);
  }
  return order;
}

void link_children(LevelTree& t) {
  t.children.assign(t.nodes.size(), {});
  for (std::uint32_t u = 0; u < t.nodes.size(); ++u) {
    if (t.nodes[u].parent != kNoParent) t.children[t.nodes[u].parent].push_back(u);
  }
}

// Da Vinci's rule on areas (III-E): a segment's area is the sum of the areas it carries, so its
// width grows as the square root of the leaves above it. The widest segment (the trunk's foot)
// is one cell, what a coefficient of the dyad describes; a fixed leaf width instead (half a
// cell) made every segment of a fine dyad half a cell to one cell wide, twigs as thick as the
// trunk, a crown of blocks.
void da_vinci(LevelTree& t) {
  const std::vector<std::uint32_t> order = breadth_first(t);
  for (HierarchyNode& n : t.nodes) n.leaves = 0;
  for (std::size_t k = order.size(); k-- > 0;) {
    HierarchyNode& n = t.nodes[order[k]];
    if (n.leaves == 0) n.leaves = 1;
    if (n.parent != kNoParent) t.nodes[n.parent].leaves += n.leaves;
  }
  std::uint32_t most = 1;
  for (const HierarchyNode& n : t.nodes) most = std::max(most, n.leaves);
  for (HierarchyNode& n : t.nodes) n.width = std::sqrt(double(n.leaves) / double(most)) * t.cell;
}

// Makes `to` a child of `from` through the points between them: an edge longer than one and a
// half cells passes the occupied cells along it (or next to it), and their centroids become
// nodes of the chain, in order along the edge. A straight trunk has no significant coefficient
// (no diagonal detail), but it has points; only where there are none is the edge straight.
void link(LevelTree& t, const CellCentroids& cc, std::uint32_t from, std::uint32_t to,
          std::uint32_t owner) {
  const Vec3 a = t.nodes[from].position, b = t.nodes[to].position;
  const Vec3 d = b - a;
  const double len = std::sqrt(dist2(d));
  std::uint32_t last = from;
  if (len > 1.5 * t.cell) {
    const int steps = int(std::floor(len / t.cell));
    const std::array<int, 3> end_a = cc.cell_of(t.level, a), end_b = cc.cell_of(t.level, b);
    std::array<int, 3> used{-1, -1, -1};
    double done = 0;  // the chain only moves forward along the edge
    for (int s = 1; s < steps; ++s) {
      const Vec3 q = a + d * (double(s) / steps);
      const std::array<int, 3> c = cc.cell_of(t.level, q);
      // The cell the sample falls in, else the occupied neighbour nearest to the sample.
      std::array<int, 3> best_cell = c;
      std::optional<Vec3> best = cc.centroid(t.level, c);
      if (best && dist2(*best - q) > t.cell * t.cell) best.reset();
      const bool own = best.has_value();
      for (int dz = -1; dz <= 1 && !own; ++dz) {
        for (int dy = -1; dy <= 1; ++dy) {
          for (int dx = -1; dx <= 1; ++dx) {
            const std::array<int, 3> n{c[0] + dx, c[1] + dy, c[2] + dz};
            const std::optional<Vec3> m = cc.centroid(t.level, n);
            if (!m || dist2(*m - q) > t.cell * t.cell) continue;
            if (!best || dist2(*m - q) < dist2(*best - q)) {
              best = m;
              best_cell = n;
            }
          }
        }
      }
      if (!best || best_cell == used || best_cell == end_a || best_cell == end_b) continue;
      const double along = dot(*best - a, d) / (len * len);
      if (!(along > done && along < 1)) continue;
      done = along;
      used = best_cell;
      HierarchyNode n;
      n.position = *best;
      n.parent = last;
      n.owner = owner;
      last = std::uint32_t(t.nodes.size());
      t.nodes.push_back(n);
      t.cell_of.push_back({-1, -1, -1});
    }
  }
  t.nodes[to].parent = last;
}

// Joins the members of one owner by their spanning tree, rooted at `entry`.
void join_members(LevelTree& t, const CellCentroids& cc, const std::vector<std::uint32_t>& members,
                  std::uint32_t entry) {
  if (members.size() < 2) return;
  std::vector<Vec3> points;
  points.reserve(members.size());
  for (std::uint32_t m : members) points.push_back(t.nodes[m].position);
  const std::vector<MstEdge> edges = euclidean_mst(points);
  std::vector<std::vector<std::uint32_t>> adj(members.size());
  for (const MstEdge& e : edges) {
    adj[e.a].push_back(e.b);
    adj[e.b].push_back(e.a);
  }
  const std::uint32_t start =
      std::uint32_t(std::find(members.begin(), members.end(), entry) - members.begin());
  std::vector<char> seen(members.size(), 0);
  std::vector<std::uint32_t> queue{start};
  seen[start] = 1;
  for (std::size_t k = 0; k < queue.size(); ++k) {
    for (std::uint32_t v : adj[queue[k]]) {
      if (seen[v]) continue;
      seen[v] = 1;
      link(t, cc, members[queue[k]], members[v], t.nodes[members[v]].owner);
      queue.push_back(v);
    }
  }
}

LevelTree refine(const LevelTree& coarse, const DyadTree& dyad, const CellCentroids& cc,
                 const VoxelGrid& grid, const HierarchyOptions& o) {
  LevelTree t;
  t.level = dyad.level;
  t.cell = grid.voxel_size * double(grid.n) / double(std::size_t(1) << dyad.level);
  HierarchyNode base;
  base.position = coarse.nodes[0].position;
  base.owner = 0;
  t.nodes.push_back(base);

  // The significant cells of this dyad, at the centroids of their points.
  std::vector<std::array<int, 3>> cells(dyad.size());
  for (std::size_t i = 0; i < dyad.size(); ++i) cells[i] = local_cell(dyad, i);
  std::vector<Vec3> where(cells.size());
  for (std::size_t i = 0; i < cells.size(); ++i) {
    where[i] = cc.centroid(dyad.level, cells[i]).value_or(cc.centre(dyad.level, cells[i]));
  }

  // Owners: the coarse node whose cell holds the fine cell (Eq. 2-3 for one cell: scaled, the
  // same region of space; exact, translated by 2^j, which keeps the local index), else the
  // nearest coarse node.
  std::unordered_map<std::uint64_t, std::uint32_t> coarse_cell;
  for (std::uint32_t u = 0; u < coarse.nodes.size(); ++u) {
    if (coarse.cell_of[u][0] >= 0) coarse_cell.emplace(key(coarse.cell_of[u]), u);
  }
  std::vector<std::vector<std::uint32_t>> members(coarse.nodes.size());
  members[0].push_back(0);
  t.cell_of.push_back({-1, -1, -1});
  for (std::size_t i = 0; i < dyad.size(); ++i) {
    std::array<int, 3> up = cells[i];
    if (o.offset == LRuleOffset::scaled) {
      for (int& c : up) c >>= 1;
    }
    const auto it = coarse_cell.find(key(up));
    HierarchyNode n;
    n.position = where[i];
    n.owner = it != coarse_cell.end() ? it->second : nearest_node(coarse, n.position);
    members[n.owner].push_back(std::uint32_t(t.nodes.size()));
    t.nodes.push_back(n);
    t.cell_of.push_back(cells[i]);
  }
  // A coarse node with no finer cell stays, where it is (III-E saw wood there); so does every
  // trunk node, first among its members, so that its cells join the trunk where it is.
  for (std::uint32_t u = 1; u < coarse.nodes.size(); ++u) {
    if (!members[u].empty() && !coarse.nodes[u].trunk) continue;
    HierarchyNode n;
    n.position = coarse.nodes[u].position;
    n.owner = u;
    n.inherited = true;
    n.trunk = coarse.nodes[u].trunk;
    members[u].insert(members[u].begin(), std::uint32_t(t.nodes.size()));
    t.nodes.push_back(n);
    t.cell_of.push_back({-1, -1, -1});
  }

  // Entries and links, parents first: u's cells are entered at the member nearest to the entry
  // of u's parent, and that is the edge joining them to the tree.
  t.entry.assign(coarse.nodes.size(), 0);
  for (std::uint32_t u : breadth_first(coarse)) {
    if (u == 0) {
      join_members(t, cc, members[0], 0);
      continue;
    }
    const Vec3 from = t.nodes[t.entry[coarse.nodes[u].parent]].position;
    std::uint32_t best = members[u][0];
    for (std::uint32_t m : members[u]) {
      if (coarse.nodes[u].trunk) break;  // a trunk node is its cells' entry
      if (dist2(t.nodes[m].position - from) < dist2(t.nodes[best].position - from)) {
        best = m;
      }
    }
    t.entry[u] = best;
    link(t, cc, t.entry[coarse.nodes[u].parent], best, u);
    join_members(t, cc, members[u], best);
  }
  link_children(t);
  da_vinci(t);
  return t;
}

// The foot of the trunk: at the lowest height (III-A's root), under the densest column of the
// lowest 5 % of the points (ground-projected density, as Livny et al. 2010 find tree bases),
// columns one cell of the finest dyad wide. The lowest point itself is wherever a drooping
// branch or a stray return touches the ground, often metres from the trunk, and so is the mean
// of the low points under a weeping or sweeping crown; the trunk is where they are densest.
Vec3 trunk_foot(const AlignedCloud& cloud, double cell) {
  double lo = 0, hi = 0;
  for (const Vec3& p : cloud.points) {
    lo = std::min(lo, p.z);
    hi = std::max(hi, p.z);
  }
  std::map<std::pair<std::int64_t, std::int64_t>, std::uint32_t> columns;
  auto column = [&](const Vec3& p) {
    return std::pair<std::int64_t, std::int64_t>(std::int64_t(std::floor(p.x / cell)),
                                                 std::int64_t(std::floor(p.y / cell)));
  };
  for (const Vec3& p : cloud.points) {
    if (p.z <= lo + 0.05 * (hi - lo)) ++columns[column(p)];
  }
  // The densest 3 x 3 block of columns (ties: the first in (x, y) order).
  std::pair<std::int64_t, std::int64_t> best{0, 0};
  std::uint32_t most = 0;
  for (const auto& [c, n] : columns) {
    std::uint32_t around = 0;
    for (std::int64_t dx = -1; dx <= 1; ++dx) {
      for (std::int64_t dy = -1; dy <= 1; ++dy) {
        const auto it = columns.find({c.first + dx, c.second + dy});
        if (it != columns.end()) around += it->second;
      }
    }
    if (around > most) {
      most = around;
      best = c;
    }
  }
  Vec3 sum{0, 0, 0};
  double n = 0;
  for (const Vec3& p : cloud.points) {
    if (p.z > lo + 0.05 * (hi - lo)) continue;
    const auto c = column(p);
    if (std::abs(c.first - best.first) > 1 || std::abs(c.second - best.second) > 1) continue;
    sum += Vec3(p.x, p.y, 0);
    n += 1;
  }
  return n > 0 ? Vec3(sum.x / n, sum.y / n, lo) : Vec3(0, 0, lo);
}

// The trunk from the foot upwards (docs/wavelets.md, "The trunk first"): in slabs `step` thick,
// the centre of the points within `window` (horizontally) of where the trunk so far predicts
// it, moved three times to their mean; it ends at the first slab with no point there. A
// straight trunk has no significant coefficient in any dyad (no diagonal detail), so the dyad
// trees joined it through branch tips: a conifer's trunk wandered from whorl to whorl.
std::vector<Vec3> trace_trunk(const AlignedCloud& cloud, const Vec3& foot, double step,
                              double window) {
  double top = foot.z;
  for (const Vec3& p : cloud.points) top = std::max(top, p.z);
  std::vector<std::vector<Vec3>> slabs(
      std::size_t(std::max(0.0, std::ceil((top - foot.z) / step))));
  for (const Vec3& p : cloud.points) {
    const double k = std::floor((p.z - foot.z) / step + 0.5);
    if (k >= 1 && k <= double(slabs.size())) slabs[std::size_t(k) - 1].push_back(p);
  }
  std::vector<Vec3> path{foot};
  for (const std::vector<Vec3>& slab : slabs) {
    const Vec3 last = path.back();
    const Vec3 predicted = path.size() > 1 ? last + (last - path[path.size() - 2]) : last;
    const std::optional<Vec3> centre = shape::trunk_centre(slab, predicted, window);
    if (!centre) break;
    path.push_back(*centre);
  }
  return path;
}

}  // namespace

std::vector<LevelTree> tree_hierarchy(const std::vector<DyadTree>& dyads, const AlignedCloud& cloud,
                                      const VoxelGrid& grid, const HierarchyOptions& options) {
  // Level "-1": the base alone, at the scan's lowest point (the aligned frame's origin).
  LevelTree base;
  base.level = -1;
  base.cell = grid.voxel_size * double(grid.n) * 2;
  base.nodes.push_back(HierarchyNode{});
  // Columns as wide as a cell of the finest dyad (two voxels).
  const double finest = grid.voxel_size * double(std::min<std::size_t>(grid.n, 2));
  base.nodes[0].position = trunk_foot(cloud, finest);
  base.nodes[0].leaves = 1;
  base.cell_of.push_back({-1, -1, -1});
  // The trunk, in steps of a cell of the second dyad, within half of one.
  const double second = grid.voxel_size * double(grid.n) / 4;
  const std::vector<Vec3> trunk = trace_trunk(cloud, base.nodes[0].position, second, second / 4);
  for (std::size_t k = 1; k < trunk.size(); ++k) {
    HierarchyNode n;
    n.position = trunk[k];
    n.parent = std::uint32_t(k - 1);
    n.trunk = true;
    base.nodes.push_back(n);
    base.cell_of.push_back({-1, -1, -1});
  }
  link_children(base);
  std::vector<LevelTree> out;
  out.reserve(dyads.size());
  const CellCentroids cc(cloud, grid);
  const LevelTree* coarse = &base;
  for (const DyadTree& d : dyads) {
    out.push_back(refine(*coarse, d, cc, grid, options));
    coarse = &out.back();
  }
  return out;
}

}  // namespace ramus::wavelet
