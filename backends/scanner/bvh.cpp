#include "backends/scanner/bvh.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ramus::scanner {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Slab test: does the ray enter the box before t_max?
bool hit_box(const Vec3& lo, const Vec3& hi, const Vec3& o, const Vec3& inv, double t_min,
             double t_max) {
  for (int k = 0; k < 3; ++k) {
    double t0 = (lo[k] - o[k]) * inv[k], t1 = (hi[k] - o[k]) * inv[k];
    if (t0 > t1) std::swap(t0, t1);
    t_min = std::max(t_min, t0);
    t_max = std::min(t_max, t1);
    if (t_max < t_min) return false;
  }
  return true;
}

}  // namespace

TriangleBvh::TriangleBvh(std::vector<Vec3> vertices, std::vector<std::uint32_t> indices)
    : vertices_(std::move(vertices)), indices_(std::move(indices)) {
  indices_.resize(indices_.size() / 3 * 3);
  const auto n = std::uint32_t(indices_.size() / 3);
  order_.resize(n);
  std::vector<Vec3> centroids(n);
  for (std::uint32_t i = 0; i < n; ++i) {
    order_[i] = i;
    centroids[i] = (vertices_[indices_[3 * i]] + vertices_[indices_[3 * i + 1]] +
                    vertices_[indices_[3 * i + 2]]) / 3.0;
  }
  if (n) build(0, n, centroids);
}

std::uint32_t TriangleBvh::build(std::uint32_t first, std::uint32_t count,
                                 std::vector<Vec3>& centroids) {
  const auto id = std::uint32_t(nodes_.size());
  nodes_.push_back({});
  Vec3 lo{kInf, kInf, kInf}, hi = -lo, clo = lo, chi = hi;
  for (std::uint32_t i = first; i < first + count; ++i) {
    for (int c = 0; c < 3; ++c) {
      const Vec3& v = vertices_[indices_[3 * order_[i] + c]];
      for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], v[k]), hi[k] = std::max(hi[k], v[k]);
    }
    const Vec3& m = centroids[order_[i]];
    for (int k = 0; k < 3; ++k) clo[k] = std::min(clo[k], m[k]), chi[k] = std::max(chi[k], m[k]);
  }
  nodes_[id].lo = lo;
  nodes_[id].hi = hi;
  const Vec3 ext = chi - clo;
  const int axis = ext.x > ext.y ? (ext.x > ext.z ? 0 : 2) : (ext.y > ext.z ? 1 : 2);
  if (count <= 4 || ext[axis] <= 0) {
    nodes_[id].first = first;
    nodes_[id].count = count;
    return id;
  }
  const std::uint32_t mid = first + count / 2;
  std::nth_element(order_.begin() + first, order_.begin() + mid, order_.begin() + first + count,
                   [&](std::uint32_t a, std::uint32_t b) {
                     return centroids[a][axis] < centroids[b][axis] ||
                            (centroids[a][axis] == centroids[b][axis] && a < b);
                   });
  const std::uint32_t left = build(first, mid - first, centroids);
  const std::uint32_t right = build(mid, first + count - mid, centroids);
  nodes_[id].left = left;
  nodes_[id].right = right;
  return id;
}

// Moeller-Trumbore; both faces count (a laser return does not care about winding).
bool TriangleBvh::hit_triangle(std::uint32_t tri, const Vec3& o, const Vec3& d, double& t) const {
  const Vec3& a = vertices_[indices_[3 * tri]];
  const Vec3 e1 = vertices_[indices_[3 * tri + 1]] - a, e2 = vertices_[indices_[3 * tri + 2]] - a;
  const Vec3 p = cross(d, e2);
  const double det = dot(e1, p);
  if (std::abs(det) < 1e-18) return false;
  const double inv = 1.0 / det;
  const Vec3 s = o - a;
  const double u = dot(s, p) * inv;
  if (u < 0 || u > 1) return false;
  const Vec3 q = cross(s, e1);
  const double v = dot(d, q) * inv;
  if (v < 0 || u + v > 1) return false;
  t = dot(e2, q) * inv;
  return true;
}

bool TriangleBvh::intersect(const Vec3& o, const Vec3& d, double t_min, double t_max,
                            Hit& hit) const {
  if (nodes_.empty()) return false;
  const Vec3 inv{1.0 / d.x, 1.0 / d.y, 1.0 / d.z};
  bool found = false;
  std::uint32_t stack[64];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& n = nodes_[stack[--top]];
    if (!hit_box(n.lo, n.hi, o, inv, t_min, t_max)) continue;
    if (n.count > 0) {
      for (std::uint32_t i = n.first; i < n.first + n.count; ++i) {
        double t;
        if (hit_triangle(order_[i], o, d, t) && t > t_min && t < t_max) {
          t_max = t;
          hit = {t, order_[i]};
          found = true;
        }
      }
    } else if (top + 2 <= 64) {
      stack[top++] = n.left;
      stack[top++] = n.right;
    }
  }
  return found;
}

void TriangleBvh::bounds(Vec3& lo, Vec3& hi) const {
  if (nodes_.empty()) {
    lo = hi = Vec3{};
    return;
  }
  lo = nodes_[0].lo;
  hi = nodes_[0].hi;
}

}  // namespace ramus::scanner
