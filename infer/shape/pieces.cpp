#include "infer/shape/pieces.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <numeric>

#include "core/union_find.h"

namespace ramus::shape {

Pieces find_pieces(const Skeleton& s) {
  const std::size_t n = s.nodes.size();
  Pieces out;
  out.piece_of_node.assign(n, kNoPiece);
  std::vector<bool> on_edge(n, false);
  UnionFind uf(n);
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint32_t p = s.nodes[i].parent;
    if (p == kNoParent) continue;
    on_edge[i] = on_edge[p] = true;
    uf.unite(i, p);
  }

  // Endpoints that touch: bucket them on a grid of the tolerance and compare each with the
  // nodes of its 27 neighbouring buckets.
  Vec3 lo, hi;
  s.bounds(lo, hi);
  double h = hi.z - lo.z;
  if (!(h > 0)) h = std::max(hi.x - lo.x, hi.y - lo.y);  // a flat skeleton: its extent
  const double tol = kTouchShare * h;
  if (tol > 0) {
    using Key = std::array<std::int64_t, 3>;
    std::map<Key, std::vector<std::size_t>> grid;
    auto key = [&](const Vec3& q) {
      return Key{std::int64_t(std::floor((q.x - lo.x) / tol)),
                 std::int64_t(std::floor((q.y - lo.y) / tol)),
                 std::int64_t(std::floor((q.z - lo.z) / tol))};
    };
    for (std::size_t i = 0; i < n; ++i) {
      if (on_edge[i]) grid[key(s.nodes[i].position)].push_back(i);
    }
    for (std::size_t i = 0; i < n; ++i) {
      if (!on_edge[i]) continue;
      const Key k = key(s.nodes[i].position);
      for (int dx = -1; dx <= 1; ++dx) {
        for (int dy = -1; dy <= 1; ++dy) {
          for (int dz = -1; dz <= 1; ++dz) {
            const auto it = grid.find(Key{k[0] + dx, k[1] + dy, k[2] + dz});
            if (it == grid.end()) continue;
            for (std::size_t j : it->second) {
              if (j != i && distance(s.nodes[i].position, s.nodes[j].position) <= tol) {
                uf.unite(i, j);
              }
            }
          }
        }
      }
    }
  }

  std::vector<double> length(n, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint32_t p = s.nodes[i].parent;
    if (p == kNoParent) continue;
    const double l = distance(s.nodes[i].position, s.nodes[p].position);
    length[uf.find(i)] += l;
    out.total_length += l;
  }
  std::vector<std::size_t> number(n, kNoPiece);
  for (std::size_t i = 0; i < n; ++i) {
    if (!on_edge[i]) continue;
    const std::size_t root = uf.find(i);
    if (!(length[root] > 0)) continue;
    if (number[root] == kNoPiece) {
      number[root] = out.count++;
      out.largest_length = std::max(out.largest_length, length[root]);
    }
    out.piece_of_node[i] = number[root];
  }
  return out;
}

}  // namespace ramus::shape
