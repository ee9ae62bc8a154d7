#include "reconstruct/bsg/forest.h"

#include <functional>
#include <limits>
#include <queue>
#include <utility>

namespace ramus::bsg {

Forest shortest_path_forest(const Graph& graph, const std::vector<std::uint32_t>& roots) {
  const std::size_t n = graph.size();
  Forest f;
  f.parent.assign(n, kNone);
  f.tree.assign(n, kNone);
  std::vector<double> dist(n, std::numeric_limits<double>::infinity());
  std::vector<std::uint8_t> done(n, 0);
  // (distance, vertex): ties resolve by vertex index, so the forest is deterministic.
  using Item = std::pair<double, std::uint32_t>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> heap;
  for (std::uint32_t t = 0; t < roots.size(); ++t) {
    const std::uint32_t r = roots[t];
    if (dist[r] == 0) continue;  // two bases on one vertex: the first keeps it
    dist[r] = 0;
    f.tree[r] = t;
    heap.push({0.0, r});
  }
  while (!heap.empty()) {
    auto [d, u] = heap.top();
    heap.pop();
    if (done[u]) continue;
    done[u] = 1;
    f.order.push_back(u);
    for (const Arc& a : graph.adj[u]) {
      const double nd = d + a.weight;
      if (nd < dist[a.to]) {
        dist[a.to] = nd;
        f.parent[a.to] = u;
        f.tree[a.to] = f.tree[u];
        heap.push({nd, a.to});
      }
    }
  }
  return f;
}

double forest_change(const Forest& a, const Forest& b) {
  std::size_t changed = 0, reached = 0;
  for (std::size_t v = 0; v < a.parent.size(); ++v) {
    if (a.tree[v] == kNone && b.tree[v] == kNone) continue;
    ++reached;
    if (a.parent[v] != b.parent[v] || a.tree[v] != b.tree[v]) ++changed;
  }
  return reached ? double(changed) / double(reached) : 0.0;
}

Bsg extract_tree(const Graph& graph, const Forest& forest, std::uint32_t t,
                 const std::vector<std::uint32_t>& roots) {
  Bsg b;
  if (forest.tree[roots[t]] != t) return b;  // the base shares a vertex with an earlier tree
  std::vector<std::uint32_t> local(graph.size(), kNone);
  // Dijkstra's settle order puts every parent before its children.
  for (std::uint32_t v : forest.order) {
    if (forest.tree[v] != t) continue;
    local[v] = std::uint32_t(b.pos.size());
    b.pos.push_back(graph.pos[v]);
    b.vertex.push_back(v);
    b.mass.push_back(double(graph.points[v]));
    b.parent.push_back(forest.parent[v] == kNone ? kNone : local[forest.parent[v]]);
  }
  b.weight.assign(b.size(), 0.0);
  b.radius.assign(b.size(), 0.0);
  return b;
}

}  // namespace ramus::bsg
