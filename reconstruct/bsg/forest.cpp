#include "reconstruct/bsg/forest.h"

#include <algorithm>
#include <limits>
#include <utility>

namespace ramus::bsg {

namespace {

// Min-heap of vertices keyed by (distance, vertex) with decrease-key: every vertex is in it at
// most once, where a heap of (distance, vertex) pairs keeps one stale entry per relaxation. Pops
// come in the same order as from such a heap, ties by vertex index, so the forest is the same.
// Four children per node: shallower than binary, and the children share a cache line.
class VertexHeap {
 public:
  explicit VertexHeap(std::size_t n) : slot_(n, kNone) {}
  bool empty() const { return heap_.empty(); }
  // Inserts v or lowers its key to d (d must not be above its key).
  void push_or_lower(std::uint32_t v, double d) {
    std::size_t i = slot_[v];
    if (i == kNone) {
      i = heap_.size();
      heap_.push_back({d, v});
    } else {
      heap_[i].d = d;
    }
    up(i);
  }
  std::uint32_t pop() {
    const std::uint32_t top = heap_.front().v;
    slot_[top] = kNone;
    const Entry last = heap_.back();
    heap_.pop_back();
    if (!heap_.empty()) {
      heap_.front() = last;
      down(0);
    }
    return top;
  }

 private:
  struct Entry {
    double d;
    std::uint32_t v;
    bool operator<(const Entry& o) const { return d < o.d || (d == o.d && v < o.v); }
  };
  void up(std::size_t i) {
    const Entry e = heap_[i];
    while (i > 0) {
      const std::size_t p = (i - 1) / 4;
      if (!(e < heap_[p])) break;
      heap_[i] = heap_[p];
      slot_[heap_[i].v] = std::uint32_t(i);
      i = p;
    }
    heap_[i] = e;
    slot_[e.v] = std::uint32_t(i);
  }
  void down(std::size_t i) {
    const Entry e = heap_[i];
    const std::size_t n = heap_.size();
    for (;;) {
      const std::size_t first = 4 * i + 1;
      if (first >= n) break;
      std::size_t best = first;
      const std::size_t end = std::min(first + 4, n);
      for (std::size_t c = first + 1; c < end; ++c) {
        if (heap_[c] < heap_[best]) best = c;
      }
      if (!(heap_[best] < e)) break;
      heap_[i] = heap_[best];
      slot_[heap_[i].v] = std::uint32_t(i);
      i = best;
    }
    heap_[i] = e;
    slot_[e.v] = std::uint32_t(i);
  }
  std::vector<Entry> heap_;
  std::vector<std::uint32_t> slot_;  // position of each vertex in heap_, kNone when absent
};

}  // namespace

Forest shortest_path_forest(const Graph& graph, const std::vector<std::uint32_t>& roots) {
  const std::size_t n = graph.size();
  Forest f;
  f.parent.assign(n, kNone);
  f.tree.assign(n, kNone);
  f.order.reserve(n);
  std::vector<double> dist(n, std::numeric_limits<double>::infinity());
  std::vector<std::uint8_t> done(n, 0);
  VertexHeap heap(n);
  for (std::uint32_t t = 0; t < roots.size(); ++t) {
    const std::uint32_t r = roots[t];
    if (dist[r] == 0) continue;  // two bases on one vertex: the first keeps it
    dist[r] = 0;
    f.tree[r] = t;
    heap.push_or_lower(r, 0.0);
  }
  while (!heap.empty()) {
    const std::uint32_t u = heap.pop();
    done[u] = 1;
    f.order.push_back(u);
    const double d = dist[u];
    for (const Arc& a : graph.adj[u]) {
      const double nd = d + a.weight;
      if (nd < dist[a.to]) {
        dist[a.to] = nd;
        f.parent[a.to] = u;
        f.tree[a.to] = f.tree[u];
        // (A settled vertex cannot get shorter with weights >= 0; like the stale entries of a
        // pair heap, it would not be settled again.)
        if (!done[a.to]) heap.push_or_lower(a.to, nd);
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
