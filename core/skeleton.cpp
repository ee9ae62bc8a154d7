#include "core/skeleton.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ramus {

Skeleton::Children Skeleton::children() const {
  Children c;
  const std::uint32_t n = std::uint32_t(nodes.size());
  c.child_begin.assign(n + 1, 0);
  for (const auto& node : nodes) {
    if (node.parent != kNoParent && node.parent < n) ++c.child_begin[node.parent + 1];
  }
  for (std::uint32_t i = 0; i < n; ++i) c.child_begin[i + 1] += c.child_begin[i];
  c.child_index.resize(c.child_begin[n]);
  std::vector<std::uint32_t> fill(c.child_begin.begin(), c.child_begin.end() - 1);
  for (std::uint32_t i = 0; i < n; ++i) {
    std::uint32_t p = nodes[i].parent;
    if (p != kNoParent && p < n) c.child_index[fill[p]++] = i;
  }
  return c;
}

std::vector<std::uint32_t> Skeleton::roots() const {
  std::vector<std::uint32_t> r;
  for (std::uint32_t i = 0; i < nodes.size(); ++i) {
    if (nodes[i].parent == kNoParent) r.push_back(i);
  }
  return r;
}

std::string Skeleton::validate() const {
  const std::uint32_t n = std::uint32_t(nodes.size());
  for (std::uint32_t i = 0; i < n; ++i) {
    const auto& node = nodes[i];
    if (node.parent != kNoParent && node.parent >= n) {
      return "node " + std::to_string(i) + " has parent " + std::to_string(node.parent) +
             " out of range";
    }
    if (node.parent == i) return "node " + std::to_string(i) + " is its own parent";
    if (!is_finite(node.position)) return "node " + std::to_string(i) + " has a non-finite position";
    if (!std::isfinite(node.radius) || node.radius < 0) {
      return "node " + std::to_string(i) + " has an invalid radius";
    }
  }
  // Cycle check: walk up from each node, marking nodes known to reach a root.
  std::vector<std::uint8_t> state(n, 0);  // 0 unknown, 1 on current path, 2 reaches a root
  std::vector<std::uint32_t> path;
  for (std::uint32_t i = 0; i < n; ++i) {
    std::uint32_t v = i;
    path.clear();
    while (v != kNoParent && state[v] == 0) {
      state[v] = 1;
      path.push_back(v);
      v = nodes[v].parent;
    }
    if (v != kNoParent && state[v] == 1) {
      return "the parent links form a cycle through node " + std::to_string(v);
    }
    for (auto p : path) state[p] = 2;
  }
  for (std::size_t i = 0; i < organs.size(); ++i) {
    if (organs[i].node != kNoParent && organs[i].node >= n) {
      return "organ " + std::to_string(i) + " hangs from node out of range";
    }
    for (const Vec3& v : organs[i].vertices) {
      if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z)) {
        return "organ " + std::to_string(i) + " has a non-finite polygon vertex";
      }
    }
  }
  return {};
}

double Skeleton::total_length() const {
  double sum = 0;
  for (const auto& node : nodes) {
    if (node.parent != kNoParent && node.parent < nodes.size()) {
      sum += distance(node.position, nodes[node.parent].position);
    }
  }
  return sum;
}

void Skeleton::bounds(Vec3& lo, Vec3& hi) const {
  if (nodes.empty()) {
    lo = hi = Vec3{};
    return;
  }
  constexpr double inf = std::numeric_limits<double>::infinity();
  lo = {inf, inf, inf};
  hi = {-inf, -inf, -inf};
  for (const auto& node : nodes) {
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], node.position[k]);
      hi[k] = std::max(hi[k], node.position[k]);
    }
  }
}

}  // namespace ramus
