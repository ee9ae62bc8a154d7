#include "reconstruct/bsg/graph.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "reconstruct/bsg/kdtree.h"

namespace ramus::bsg {

std::size_t Graph::edge_count() const {
  std::size_t n = 0;
  for (const auto& a : adj) n += a.size();
  return n / 2;
}

bool Graph::add_edge(std::uint32_t u, std::uint32_t v, double weight) {
  if (u == v) return false;
  for (const Arc& a : adj[u]) {
    if (a.to == v) return false;
  }
  adj[u].push_back({v, weight});
  adj[v].push_back({u, weight});
  return true;
}

bool Graph::scale_edge(std::uint32_t u, std::uint32_t v, double factor) {
  bool found = false;
  for (Arc& a : adj[u]) {
    if (a.to == v) a.weight *= factor, found = true;
  }
  for (Arc& a : adj[v]) {
    if (a.to == u) a.weight *= factor;
  }
  return found;
}

std::vector<std::vector<std::uint32_t>> children_of(const std::vector<std::uint32_t>& parent) {
  std::vector<std::vector<std::uint32_t>> ch(parent.size());
  for (std::uint32_t i = 0; i < parent.size(); ++i) {
    if (parent[i] != kNone) ch[parent[i]].push_back(i);
  }
  return ch;
}

void append_node(Bsg& to, const Bsg& from, std::uint32_t v, std::uint32_t parent) {
  to.pos.push_back(from.pos[v]);
  to.parent.push_back(parent);
  to.vertex.push_back(from.vertex[v]);
  to.weight.push_back(from.weight[v]);
  to.radius.push_back(from.radius[v]);
  to.mass.push_back(from.mass[v]);
}

Bsg depth_first(const Bsg& b, const std::vector<std::vector<std::uint32_t>>& children,
                std::vector<std::uint32_t>* old_of) {
  Bsg out;
  if (old_of) old_of->clear();
  std::vector<std::uint32_t> stack{0}, local(b.size(), kNone);
  while (!stack.empty()) {
    const std::uint32_t v = stack.back();
    stack.pop_back();
    local[v] = std::uint32_t(out.size());
    append_node(out, b, v, b.parent[v] == kNone ? kNone : local[b.parent[v]]);
    if (old_of) old_of->push_back(v);
    for (auto it = children[v].rbegin(); it != children[v].rend(); ++it) stack.push_back(*it);
  }
  return out;
}

Graph voxelize(const std::vector<Eigen::Vector3d>& points, const std::vector<std::uint8_t>& keep,
               double voxel, std::vector<std::uint32_t>& point_vertex) {
  // Sorting (key, point) pairs instead of hashing keeps the vertex order independent of any
  // hash table's iteration order.
  std::vector<std::pair<std::uint64_t, std::uint32_t>> keyed;
  keyed.reserve(points.size());
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (keep[i]) lo = lo.cwiseMin(points[i]);
  }
  for (std::uint32_t i = 0; i < points.size(); ++i) {
    if (!keep[i]) continue;
    Eigen::Vector3d c = ((points[i] - lo) / voxel).array().floor();
    // 21 bits per axis: 2 million voxels along each axis is far beyond any sensible grid.
    auto q = [](double x) { return std::uint64_t(std::clamp(x, 0.0, 2097151.0)); };
    keyed.emplace_back((q(c.z()) << 42) | (q(c.y()) << 21) | q(c.x()), i);
  }
  std::sort(keyed.begin(), keyed.end());
  Graph g;
  point_vertex.assign(points.size(), kNone);
  for (std::size_t i = 0; i < keyed.size();) {
    std::size_t j = i;
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    const auto v = std::uint32_t(g.pos.size());
    for (; j < keyed.size() && keyed[j].first == keyed[i].first; ++j) {
      sum += points[keyed[j].second];
      point_vertex[keyed[j].second] = v;
    }
    g.pos.push_back(sum / double(j - i));
    g.points.push_back(std::uint32_t(j - i));
    i = j;
  }
  g.adj.resize(g.pos.size());
  return g;
}

void link_nearest(Graph& graph, int k) {
  if (graph.size() < 2) return;
  link_nearest(graph, k, PointIndex(graph.pos));
}

void link_nearest(Graph& graph, int k, const PointIndex& index) {
  if (graph.size() < 2) return;
  const std::size_t kk = std::min<std::size_t>(std::size_t(k) + 1, graph.size());
  // The queries run in parallel into fixed slots; edges are then added in vertex order, so the
  // graph does not depend on the schedule.
  std::vector<std::uint32_t> ids(graph.size() * kk, kNone);
  std::vector<double> d2(graph.size() * kk);
  tbb::parallel_for(tbb::blocked_range<std::uint32_t>(0, std::uint32_t(graph.size()), 1024),
                    [&](const tbb::blocked_range<std::uint32_t>& r) {
                      for (std::uint32_t v = r.begin(); v != r.end(); ++v) {
                        index.knn(graph.pos[v], kk, &ids[v * kk], &d2[v * kk]);
                      }
                    });
  for (std::uint32_t v = 0; v < graph.size(); ++v) {
    for (std::size_t j = 0; j < kk; ++j) {
      const std::uint32_t u = ids[v * kk + j];
      if (u != kNone && u != v) graph.add_edge(v, u, d2[v * kk + j]);
    }
  }
}

void contract(Graph& graph, int steps) {
  std::vector<Eigen::Vector3d> next(graph.size());
  for (int s = 0; s < steps; ++s) {
    tbb::parallel_for(tbb::blocked_range<std::uint32_t>(0, std::uint32_t(graph.size()), 4096),
                      [&](const tbb::blocked_range<std::uint32_t>& r) {
                        for (std::uint32_t v = r.begin(); v != r.end(); ++v) {
                          Eigen::Vector3d sum = graph.pos[v];
                          for (const Arc& a : graph.adj[v]) sum += graph.pos[a.to];
                          next[v] = sum / double(graph.adj[v].size() + 1);
                        }
                      });
    graph.pos.swap(next);
  }
  // Edge weights follow the moved vertices.
  for (std::uint32_t v = 0; v < graph.size(); ++v) {
    for (Arc& a : graph.adj[v]) a.weight = (graph.pos[v] - graph.pos[a.to]).squaredNorm();
  }
}

std::vector<std::uint32_t> components(const Graph& graph, std::uint32_t* count) {
  std::vector<std::uint32_t> label(graph.size(), kNone);
  std::vector<std::uint32_t> stack;
  std::uint32_t next = 0;
  for (std::uint32_t s = 0; s < graph.size(); ++s) {
    if (label[s] != kNone) continue;
    label[s] = next;
    stack.assign(1, s);
    while (!stack.empty()) {
      std::uint32_t u = stack.back();
      stack.pop_back();
      for (const Arc& a : graph.adj[u]) {
        if (label[a.to] == kNone) label[a.to] = next, stack.push_back(a.to);
      }
    }
    ++next;
  }
  if (count) *count = next;
  return label;
}

}  // namespace ramus::bsg
