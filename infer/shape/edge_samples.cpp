#include "infer/shape/edge_samples.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "infer/shape/shape_error.h"

namespace ramus::shape {

bool segment_z_range(const Skeleton& s, double& z_min, double& z_max) {
  bool any = false;
  for (std::size_t i = 0; i < s.nodes.size(); ++i) {
    const std::uint32_t p = s.nodes[i].parent;
    if (p == kNoParent) continue;
    for (const Vec3& q : {s.nodes[i].position, s.nodes[p].position}) {
      z_min = any ? std::min(z_min, q.z) : q.z;
      z_max = any ? std::max(z_max, q.z) : q.z;
      any = true;
    }
  }
  return any;
}

std::vector<Vec3> sample_edges(const Skeleton& s, double step, std::size_t max_samples) {
  if (!(step > 0) || !std::isfinite(step)) {
    throw ShapeError("the sample spacing must be a positive number");
  }
  // Count first, so that a skeleton far larger than the spacing fails with a message instead
  // of exhausting memory.
  std::vector<bool> starts(s.nodes.size(), false);
  double count = 0;
  for (std::size_t i = 0; i < s.nodes.size(); ++i) {
    const std::uint32_t p = s.nodes[i].parent;
    if (p == kNoParent) continue;
    count += std::max(1.0, std::ceil(distance(s.nodes[i].position, s.nodes[p].position) / step));
    if (s.nodes[p].parent == kNoParent) starts[p] = true;
  }
  for (bool b : starts) count += b ? 1 : 0;
  if (count > double(max_samples)) {
    throw ShapeError("the skeleton would need " + std::to_string(std::llround(count)) +
                     " samples at a spacing of " + std::to_string(step) +
                     " (its size is far beyond the reference's)");
  }
  std::vector<Vec3> out;
  out.reserve(std::size_t(count));
  for (std::size_t i = 0; i < s.nodes.size(); ++i) {
    if (starts[i]) out.push_back(s.nodes[i].position);
    const std::uint32_t p = s.nodes[i].parent;
    if (p == kNoParent) continue;
    const Vec3 a = s.nodes[p].position, b = s.nodes[i].position;
    const int n = int(std::max(1.0, std::ceil(distance(a, b) / step)));
    for (int k = 1; k < n; ++k) out.push_back(a + (b - a) * (double(k) / n));
    out.push_back(b);  // exactly the node, not a rounded interpolation
  }
  return out;
}

}  // namespace ramus::shape
