#pragma once
// Disjoint sets over the indices 0..n-1 with path halving. The smaller index of two joined sets
// becomes their root, so roots (and anything ordered by them) do not depend on the order in
// which sets are joined.
#include <algorithm>
#include <cstdint>
#include <numeric>
#include <vector>

namespace ramus {

class UnionFind {
 public:
  explicit UnionFind(std::size_t n) : parent_(n) {
    std::iota(parent_.begin(), parent_.end(), std::uint32_t(0));
  }

  std::uint32_t find(std::uint32_t x) {
    while (parent_[x] != x) x = parent_[x] = parent_[parent_[x]];
    return x;
  }

  // Joins the sets of a and b; false when they were one set already.
  bool unite(std::uint32_t a, std::uint32_t b) {
    a = find(a);
    b = find(b);
    if (a == b) return false;
    parent_[std::max(a, b)] = std::min(a, b);
    return true;
  }

 private:
  std::vector<std::uint32_t> parent_;
};

}  // namespace ramus
