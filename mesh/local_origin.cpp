#include "mesh/local_origin.h"

#include <algorithm>
#include <cmath>

namespace ramus::mesh {
namespace {

double largest_coordinate(const Vec3& v) {
  return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
}

}  // namespace

Vec3 local_origin(const Skeleton& s) {
  // Non-finite positions are left for build_tree_mesh to report with the node's index.
  double far = 0;
  for (const SkeletonNode& n : s.nodes) far = std::max(far, largest_coordinate(n.position));
  for (const OrganAnchor& a : s.organs) {
    far = std::max(far, largest_coordinate(a.position));
    for (const Vec3& v : a.vertices) far = std::max(far, largest_coordinate(v));
  }
  if (!(far > kFloatMillimetreRange) || !std::isfinite(far)) return {};
  Vec3 lo, hi;
  s.bounds(lo, hi);
  return {std::round((lo.x + hi.x) / 2), std::round((lo.y + hi.y) / 2), std::round(lo.z)};
}

Skeleton relative_to(const Skeleton& s, const Vec3& origin) {
  Skeleton out = s;
  for (SkeletonNode& n : out.nodes) n.position -= origin;
  for (OrganAnchor& a : out.organs) {
    a.position -= origin;
    for (Vec3& v : a.vertices) v -= origin;
  }
  return out;
}

}  // namespace ramus::mesh
