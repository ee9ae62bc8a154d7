#include "reconstruct/bsg/chain_order.h"

#include <algorithm>
#include <limits>
#include <numeric>
#include <vector>

namespace ramus::bsg {

namespace {

// The nodes of the chain that starts at `first` (a child of a fork or of the root): its inner
// nodes (one child each) and the fork or tip that ends it.
std::uint32_t chain_from(std::uint32_t first, const std::vector<std::vector<std::uint32_t>>& ch,
                         std::vector<std::uint32_t>& inner) {
  inner.clear();
  std::uint32_t end = first;
  while (ch[end].size() == 1) inner.push_back(end), end = ch[end][0];
  return end;
}

// Distance from x to the polyline `line`.
double distance_to(const std::vector<Eigen::Vector3d>& line, const Eigen::Vector3d& x) {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k + 1 < line.size(); ++k) {
    const Eigen::Vector3d a = line[k], ab = line[k + 1] - a;
    const double l2 = ab.squaredNorm();
    const double t = l2 > 0 ? std::clamp((x - a).dot(ab) / l2, 0.0, 1.0) : 0.0;
    best = std::min(best, (x - a - t * ab).norm());
  }
  return best;
}

}  // namespace

std::size_t return_nodes_behind_forks(Bsg& b, double min_radius) {
  const std::size_t n = b.size();
  if (n < 4) return 0;
  auto ch = children_of(b.parent);
  std::size_t moved = 0;
  std::vector<std::uint32_t> inner, below, behind;
  std::vector<Eigen::Vector3d> stem;
  for (std::uint32_t s = 0; s < n; ++s) {
    if (ch[s].size() < 2 || b.parent[s] == kNone) continue;
    // The stem below the fork (its chain down to the fork or root it leaves, `below` its inner
    // nodes from the bottom up), gathered the first time a chain of the fork starts behind it.
    std::uint32_t q0 = kNone;
    auto gather_stem = [&] {
      below.clear();
      q0 = b.parent[s];
      while (b.parent[q0] != kNone && ch[q0].size() == 1) below.push_back(q0), q0 = b.parent[q0];
      std::reverse(below.begin(), below.end());
      stem.assign(1, b.pos[q0]);
      for (std::uint32_t v : below) stem.push_back(b.pos[v]);
      stem.push_back(b.pos[s]);
    };
    const double reach = std::max(b.radius[s], min_radius);
    for (std::uint32_t first : std::vector<std::uint32_t>(ch[s])) {
      const std::uint32_t end = chain_from(first, ch, inner);
      const Eigen::Vector3d chord = b.pos[end] - b.pos[s];
      if (inner.empty() || !(chord.norm() > 0)) continue;
      const Eigen::Vector3d u = chord.normalized();
      if ((b.pos[inner[0]] - b.pos[s]).dot(u) >= 0) continue;  // it starts ahead (most do)
      if (q0 == kNone) gather_stem();
      // The leading inner nodes behind the fork, on the axis of the stem below it.
      behind.clear();
      for (std::uint32_t v : inner) {
        if ((b.pos[v] - b.pos[s]).dot(u) >= 0 || b.radius[v] < min_radius) break;
        if (distance_to(stem, b.pos[v]) > reach) break;
        behind.push_back(v);
      }
      if (behind.empty()) continue;
      // The chain goes on from the fork at its first node ahead; the nodes behind join the
      // stem below, in order along its chord.
      const std::uint32_t next = behind.size() < inner.size() ? inner[behind.size()] : end;
      b.parent[next] = s;
      std::replace(ch[s].begin(), ch[s].end(), first, next);
      std::vector<std::uint32_t> all = below;
      all.insert(all.end(), behind.begin(), behind.end());
      const Eigen::Vector3d a = b.pos[q0], axis = b.pos[s] - a;
      std::stable_sort(all.begin(), all.end(), [&](std::uint32_t x, std::uint32_t y) {
        return (b.pos[x] - a).dot(axis) < (b.pos[y] - a).dot(axis);
      });
      std::uint32_t prev = q0;
      std::replace(ch[q0].begin(), ch[q0].end(), below.empty() ? s : below.front(), all.front());
      for (std::uint32_t v : all) {
        b.parent[v] = prev;
        if (prev != q0) ch[prev].assign(1, v);
        prev = v;
      }
      b.parent[s] = prev;
      ch[prev].assign(1, s);
      gather_stem();  // the stem as it is now, for the fork's next chain
      moved += behind.size();
    }
  }
  if (moved > 0) b = depth_first(b, ch);
  return moved;
}

// A chain that winds over a stem's bark steps back along its chord by at most about the stem's
// diameter once centred (over the harness trees at most 2.2 of the chain's largest radii); one
// that runs out along a branch and back along another (two whips joined at their tips: 29 radii
// on the weeping tree from one station) is not a winding stem, and sorting it interleaves the two
// branches' nodes into a comb between them.
constexpr double kMaxStepBack = 3.0;

std::size_t order_chains_along_axes(Bsg& b, double min_radius) {
  const std::size_t n = b.size();
  if (n < 3) return 0;
  const auto ch = children_of(b.parent);
  std::size_t sorted = 0;
  std::vector<std::uint32_t> inner, idx;
  std::vector<double> t;
  std::vector<Eigen::Vector3d> pos;
  std::vector<double> radius;
  for (std::uint32_t s = 0; s < n; ++s) {
    // Chains start at the root and at the children of forks.
    if (b.parent[s] != kNone && ch[s].size() == 1) continue;
    for (std::uint32_t first : ch[s]) {
      inner.clear();
      std::uint32_t end = first;
      while (ch[end].size() == 1) inner.push_back(end), end = ch[end][0];
      if (inner.size() < 2) continue;
      const Eigen::Vector3d a = b.pos[s], chord = b.pos[end] - a;
      const double length = chord.norm();
      if (!(length > 0)) continue;
      const Eigen::Vector3d u = chord / length;
      t.clear();
      bool thick = false, straight = true;
      double ahead = -std::numeric_limits<double>::infinity(), back = 0, widest = 0;
      for (std::uint32_t v : inner) {
        const Eigen::Vector3d q = b.pos[v] - a;
        t.push_back(q.dot(u));
        thick |= b.radius[v] >= min_radius;
        straight &= (q - t.back() * u).norm() <= 0.5 * length;
        ahead = std::max(ahead, t.back());
        back = std::max(back, ahead - t.back());
        widest = std::max(widest, b.radius[v]);
      }
      if (!thick || !straight || back > kMaxStepBack * widest || back == 0) continue;
      idx.resize(inner.size());
      std::iota(idx.begin(), idx.end(), 0u);
      std::stable_sort(idx.begin(), idx.end(),
                       [&](std::uint32_t i, std::uint32_t j) { return t[i] < t[j]; });
      pos.clear(), radius.clear();
      for (std::uint32_t i : idx)
        pos.push_back(b.pos[inner[i]]), radius.push_back(b.radius[inner[i]]);
      for (std::size_t k = 0; k < inner.size(); ++k) {
        b.pos[inner[k]] = pos[k];
        b.radius[inner[k]] = radius[k];
      }
      ++sorted;
    }
  }
  return sorted;
}

}  // namespace ramus::bsg
