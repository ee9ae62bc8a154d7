// A bounding volume hierarchy over triangles for the simulated scanner's ray casts: median
// splits along the longest axis of the centroid bounds, up to 4 triangles per leaf.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "core/vec3.h"

namespace ramus::scanner {

struct Hit {
  double t = 0;  // distance along the (unit) ray direction
  std::uint32_t triangle = 0;
};

class TriangleBvh {
 public:
  // Triangles are given as vertex positions and index triples.
  TriangleBvh(std::vector<Vec3> vertices, std::vector<std::uint32_t> indices);

  // The nearest hit with t in (t_min, t_max), if any.
  bool intersect(const Vec3& origin, const Vec3& dir, double t_min, double t_max, Hit& hit) const;

  std::size_t triangle_count() const { return indices_.size() / 3; }
  void bounds(Vec3& lo, Vec3& hi) const;

 private:
  struct Node {
    Vec3 lo, hi;
    std::uint32_t first = 0, count = 0;  // leaf: triangles order_[first, first + count)
    std::uint32_t left = 0, right = 0;   // inner: children
  };
  std::uint32_t build(std::uint32_t first, std::uint32_t count, std::vector<Vec3>& centroids);
  bool hit_triangle(std::uint32_t tri, const Vec3& o, const Vec3& d, double& t) const;

  std::vector<Vec3> vertices_;
  std::vector<std::uint32_t> indices_;
  std::vector<std::uint32_t> order_;
  std::vector<Node> nodes_;
};

}  // namespace ramus::scanner
