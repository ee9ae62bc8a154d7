#include "reconstruct/bsg/chain_order.h"

#include <algorithm>
#include <numeric>
#include <vector>

namespace ramus::bsg {

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
      for (std::uint32_t v : inner) {
        const Eigen::Vector3d q = b.pos[v] - a;
        t.push_back(q.dot(u));
        thick |= b.radius[v] >= min_radius;
        straight &= (q - t.back() * u).norm() <= 0.5 * length;
      }
      if (!thick || !straight || std::is_sorted(t.begin(), t.end())) continue;
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
