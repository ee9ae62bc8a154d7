// Boruvka EMST (see emst.h). References: O. Boruvka (1926); W. March, P. Ram & A. Gray, "Fast
// Euclidean minimum spanning tree: algorithm, analysis, and applications", KDD 2010 (the
// component-pruned nearest-neighbour search, here in its single-tree form).
#include "infer/wavelet/emst.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <nanoflann.hpp>
#include <numeric>
#include <stdexcept>
#include <string>
#include <tuple>

#include "core/union_find.h"

namespace ramus::wavelet {
namespace {

struct Cloud {
  const std::vector<Vec3>& pts;
  std::size_t kdtree_get_point_count() const { return pts.size(); }
  double kdtree_get_pt(std::size_t i, std::size_t d) const { return pts[i][int(d)]; }
  template <class Box>
  bool kdtree_get_bbox(Box&) const {
    return false;
  }
};

using Tree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, Cloud>, Cloud,
                                                 3, std::uint32_t>;

constexpr std::uint32_t kNone = 0xffffffffu;
constexpr double kInf = std::numeric_limits<double>::infinity();

// A candidate edge from `from`, ordered by (squared length, smaller index, larger index).
struct Candidate {
  double d2 = kInf;
  std::uint32_t from = kNone, to = kNone;
  auto key() const { return std::tuple(d2, std::min(from, to), std::max(from, to)); }
  bool better_than(const Candidate& o) const { return o.to == kNone || key() < o.key(); }
};

// nanoflann result set: the best point outside component `comp` seen from point `from` that beats
// `bound` (the component's best edge so far).
struct OutsideResult {
  const std::vector<std::uint32_t>& comp_of;
  std::uint32_t comp, from;
  Candidate bound, best;
  // nanoflann only offers points strictly closer than worstDist(); equal lengths must be offered
  // too, for the index tie-break.
  double worstDist() const {
    double d = std::min(best.to == kNone ? kInf : best.d2, bound.to == kNone ? kInf : bound.d2);
    return std::nextafter(d, kInf);
  }
  bool full() const { return true; }
  bool addPoint(double d2, std::uint32_t index) {
    if (comp_of[index] == comp) return true;
    Candidate c{d2, from, index};
    if (c.better_than(best) && c.better_than(bound)) best = c;
    return true;
  }
};

constexpr std::size_t kListed = 12;

// The k nearest other points of point i, sorted by (squared distance, index).
void nearest_neighbours(const Tree& tree, const std::vector<Vec3>& points, std::uint32_t i,
                        std::size_t k, std::uint32_t* index, double* d2) {
  std::vector<std::uint32_t> idx(k + 1);
  std::vector<double> dist(k + 1);
  const double q[3] = {points[i].x, points[i].y, points[i].z};
  std::size_t found = tree.knnSearch(q, k + 1, idx.data(), dist.data());
  std::vector<std::pair<double, std::uint32_t>> list;
  for (std::size_t m = 0; m < found; ++m) {
    if (idx[m] != i) list.push_back({dist[m], idx[m]});
  }
  // Among equal distances the search may return any subset; keep the k best by (d2, index).
  std::sort(list.begin(), list.end());
  list.resize(k);
  for (std::size_t m = 0; m < k; ++m) {
    index[m] = list[m].second;
    d2[m] = list[m].first;
  }
}

}  // namespace

std::vector<MstEdge> euclidean_mst(const std::vector<Vec3>& points) {
  const std::size_t n = points.size();
  for (std::size_t i = 0; i < n; ++i) {
    if (!is_finite(points[i])) {
      throw std::invalid_argument("point " + std::to_string(i) + " has a non-finite coordinate");
    }
  }
  std::vector<MstEdge> edges;
  if (n < 2) return edges;
  Cloud cloud{points};
  Tree tree(3, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(16));
  tree.buildIndex();

  // Each point's nearest neighbours, sorted by (squared length, index): most points find their
  // nearest point outside their component in this list and need no tree query.
  const std::size_t k = std::min<std::size_t>(kListed, n - 1);
  std::vector<std::uint32_t> listed(n * k);
  std::vector<double> listed_d2(n * k);
  for (std::uint32_t i = 0; i < n; ++i) {
    nearest_neighbours(tree, points, i, k, &listed[i * k], &listed_d2[i * k]);
  }
  std::vector<std::uint8_t> cursor(n, 0);

  UnionFind uf(n);
  std::vector<std::uint32_t> comp_of(n);
  std::vector<Candidate> cached(n);  // each point's nearest point outside its component, if known
  std::vector<Candidate> best(n);    // per component root
  std::vector<std::uint32_t> ask;    // points whose answer is not in their list
  std::size_t components = n;
  while (components > 1) {
    for (std::uint32_t i = 0; i < n; ++i) comp_of[i] = uf.find(i);
    for (Candidate& c : best) c = Candidate{};
    ask.clear();
    for (std::uint32_t i = 0; i < n; ++i) {
      const std::uint32_t ci = comp_of[i];
      // Components only grow, so a listed neighbour once inside stays inside.
      while (cursor[i] < k && comp_of[listed[i * k + cursor[i]]] == ci) ++cursor[i];
      // Every point strictly closer than the last listed one is listed, so a listed outside point
      // closer than that is the true nearest; at the last distance an unlisted tie may win.
      if (cursor[i] < k && listed_d2[i * k + cursor[i]] < listed_d2[i * k + k - 1]) {
        Candidate c{listed_d2[i * k + cursor[i]], i, listed[i * k + cursor[i]]};
        if (c.better_than(best[ci])) best[ci] = c;
      } else {
        ask.push_back(i);
      }
    }
    for (std::uint32_t i : ask) {
      const std::uint32_t ci = comp_of[i];
      // The nearest outside point is at least as far as the last listed one: skip the query when
      // the component already has a shorter edge.
      if (best[ci].to != kNone && best[ci].d2 < listed_d2[i * k + k - 1]) continue;
      Candidate& mine = cached[i];
      if (mine.to == kNone || comp_of[mine.to] == ci) {
        // Only an edge that beats the component's best matters, so the search is bounded by it.
        // A hit is then the point's true nearest outside neighbour and can be kept for later
        // rounds; a miss says nothing about it, so the point is asked again next round.
        OutsideResult r{comp_of, ci, i, best[ci], Candidate{}};
        const double q[3] = {points[i].x, points[i].y, points[i].z};
        tree.findNeighbors(r, q, nanoflann::SearchParams());
        mine = r.best;
        if (mine.to == kNone) continue;
      }
      if (mine.better_than(best[ci])) best[ci] = mine;
    }
    for (std::uint32_t c = 0; c < n; ++c) {
      const Candidate& e = best[c];
      if (e.to == kNone || !uf.unite(e.from, e.to)) continue;
      edges.push_back({std::min(e.from, e.to), std::max(e.from, e.to), std::sqrt(e.d2)});
      components -= 1;
    }
  }
  return edges;
}

double total_length(const std::vector<MstEdge>& edges) {
  double sum = 0;
  for (const MstEdge& e : edges) sum += e.length;
  return sum;
}

}  // namespace ramus::wavelet
