#include "infer/wavelet/dyad_tree.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <tuple>

#include "infer/wavelet/emst.h"

namespace ramus::wavelet {
namespace {

template <class F>
void for_each_cell(const CoefficientBlock& b, F&& f) {
  for (std::size_t k = 0; k < b.size[2]; ++k) {
    for (std::size_t j = 0; j < b.size[1]; ++j) {
      for (std::size_t i = 0; i < b.size[0]; ++i) f(i, j, k);
    }
  }
}

struct Adjacency {
  std::vector<std::uint32_t> begin, next;
};

Adjacency adjacency(std::size_t n, const std::vector<MstEdge>& edges) {
  Adjacency adj;
  adj.begin.assign(n + 1, 0);
  for (const MstEdge& e : edges) {
    adj.begin[e.a + 1]++;
    adj.begin[e.b + 1]++;
  }
  for (std::size_t i = 0; i < n; ++i) adj.begin[i + 1] += adj.begin[i];
  adj.next.resize(adj.begin[n]);
  std::vector<std::uint32_t> fill(adj.begin.begin(), adj.begin.end() - 1);
  for (const MstEdge& e : edges) {
    adj.next[fill[e.a]++] = e.b;
    adj.next[fill[e.b]++] = e.a;
  }
  return adj;
}

// Breadth-first order from the root; sets parents.
std::vector<std::uint32_t> orient(DyadTree& t, const std::vector<MstEdge>& edges) {
  Adjacency adj = adjacency(t.size(), edges);
  t.parent.assign(t.size(), kNoParent);
  std::vector<std::uint32_t> order{t.root};
  std::vector<char> seen(t.size(), 0);
  seen[t.root] = 1;
  for (std::size_t k = 0; k < order.size(); ++k) {
    std::uint32_t u = order[k];
    for (std::uint32_t e = adj.begin[u]; e < adj.begin[u + 1]; ++e) {
      std::uint32_t v = adj.next[e];
      if (seen[v]) continue;
      seen[v] = 1;
      t.parent[v] = u;
      order.push_back(v);
    }
  }
  return order;
}

std::uint32_t lowest(const DyadTree& t) {
  std::uint32_t best = 0;
  for (std::uint32_t i = 1; i < t.size(); ++i) {
    const auto& a = t.cells[i];
    const auto& b = t.cells[best];
    if (std::tuple(a[2], a[1], a[0]) < std::tuple(b[2], b[1], b[0])) best = i;
  }
  return best;
}

}  // namespace

DyadTree dyad_tree(const WaveletPyramid& pyramid, int level, const DyadTreeOptions& options) {
  DyadTree t;
  t.level = level;
  t.subband = options.subband;
  t.block = pyramid.subband(level, options.subband);
  const CoefficientBlock& b = t.block;
  double cut = options.threshold;
  if (options.mode == ThresholdMode::relative_to_dyad_max) {
    double most = 0;
    for_each_cell(b, [&](std::size_t i, std::size_t j, std::size_t k) {
      most = std::max(most, std::abs(pyramid.at(b, i, j, k)));
    });
    cut *= most;
  }
  std::vector<Vec3> points;
  for_each_cell(b, [&](std::size_t i, std::size_t j, std::size_t k) {
    double c = pyramid.at(b, i, j, k);
    if (!(std::abs(c) > cut) || c == 0.0) return;
    t.cells.push_back({int(b.offset[0] + i), int(b.offset[1] + j), int(b.offset[2] + k)});
    t.coefficients.push_back(c);
    points.push_back(Vec3(double(i), double(j), double(k)));
  });
  if (points.empty()) return t;
  std::vector<MstEdge> edges = euclidean_mst(points);
  t.length = total_length(edges);
  t.root = lowest(t);
  std::vector<std::uint32_t> order = orient(t, edges);
  // Da Vinci (III-E): a segment carries the leaves above it; area is proportional to that count.
  t.leaves.assign(t.size(), 0);
  for (std::size_t k = order.size(); k-- > 0;) {
    std::uint32_t u = order[k];
    if (t.leaves[u] == 0) t.leaves[u] = 1;
    if (t.parent[u] != kNoParent) t.leaves[t.parent[u]] += t.leaves[u];
  }
  return t;
}

std::vector<DyadTree> dyad_trees(const WaveletPyramid& pyramid, const DyadTreeOptions& options) {
  std::vector<DyadTree> out;
  for (int j = 0; j < pyramid.levels(); ++j) out.push_back(dyad_tree(pyramid, j, options));
  return out;
}

Skeleton to_skeleton(const DyadTree& tree, const WaveletPyramid& pyramid,
                     const DyadTreeOptions& options, const Alignment* alignment) {
  Skeleton sk;
  if (tree.root == kNoParent) return sk;
  const VoxelGrid& g = pyramid.coefficients;
  // A cell of dyad j covers n / 2^j voxels of the transformed grid along each axis.
  const double cell = g.voxel_size * double(g.n) / double(tree.block.size[0]);
  auto position = [&](std::uint32_t u) {
    Vec3 local;
    for (int k = 0; k < 3; ++k) {
      local[k] = double(tree.cells[u][k] - int(tree.block.offset[k])) + 0.5;
    }
    Vec3 p = g.origin + local * cell;
    return alignment ? alignment->to_world(p) : p;
  };
  // Breadth-first from the root, so that parents precede children in the skeleton.
  std::vector<std::vector<std::uint32_t>> kids(tree.size());
  for (std::uint32_t u = 0; u < tree.size(); ++u) {
    if (tree.parent[u] != kNoParent) kids[tree.parent[u]].push_back(u);
  }
  std::vector<std::uint32_t> order{tree.root}, node_of(tree.size(), kNoParent);
  const double leaf_radius = options.leaf_radius * cell;
  for (std::size_t k = 0; k < order.size(); ++k) {
    const std::uint32_t u = order[k];
    SkeletonNode n;
    n.position = position(u);
    n.radius = leaf_radius * std::sqrt(double(tree.leaves[u]));
    if (tree.parent[u] != kNoParent) {
      const SkeletonNode& p = sk.nodes[node_of[tree.parent[u]]];
      n.parent = node_of[tree.parent[u]];
      n.heading = normalized(n.position - p.position);
      n.left = normalized(cross(Vec3{0, 0, 1}, n.heading), Vec3{-1, 0, 0});
      n.up = cross(n.heading, n.left);
      // The child carrying most leaves continues its parent's axis; the others branch off.
      std::uint32_t main = *std::max_element(
          kids[tree.parent[u]].begin(), kids[tree.parent[u]].end(),
          [&](std::uint32_t a, std::uint32_t b) { return tree.leaves[a] < tree.leaves[b]; });
      n.order = std::uint16_t(p.order + (main == u ? 0 : 1));
    }
    node_of[u] = sk.add(n);
    for (std::uint32_t v : kids[u]) order.push_back(v);
  }
  return sk;
}

}  // namespace ramus::wavelet
