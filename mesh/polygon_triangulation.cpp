#include "mesh/polygon_triangulation.h"

#include <algorithm>
#include <cmath>

#include "mesh/frames.h"

namespace ramus::mesh {

namespace {

struct P2 {
  double x = 0, y = 0;
};

double cross2(const P2& o, const P2& a, const P2& b) {
  return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

// Whether p lies inside or on triangle (a, b, c), which is counter-clockwise.
bool in_triangle(const P2& p, const P2& a, const P2& b, const P2& c) {
  return cross2(a, b, p) >= 0 && cross2(b, c, p) >= 0 && cross2(c, a, p) >= 0;
}

}  // namespace

PolygonTriangles triangulate_polygon(const std::vector<Vec3>& outline) {
  PolygonTriangles out;
  const std::size_t n = outline.size();
  if (n < 3) return out;
  // Newell's method: the normal of the best-fit plane, its length twice the projected area.
  Vec3 normal{0, 0, 0};
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3& a = outline[i];
    const Vec3& b = outline[(i + 1) % n];
    normal.x += (a.y - b.y) * (a.z + b.z);
    normal.y += (a.z - b.z) * (a.x + b.x);
    normal.z += (a.x - b.x) * (a.y + b.y);
  }
  double extent = 0;
  for (const Vec3& v : outline) extent = std::max(extent, length(v - outline[0]));
  if (!(length(normal) > 1e-12 * std::max(1.0, extent * extent))) return out;
  out.normal = normalized(normal);
  const Vec3 e1 = any_perpendicular(out.normal);
  const Vec3 e2 = cross(out.normal, e1);
  // In (e1, e2) the outline runs counter-clockwise, since Newell's normal follows its winding.
  std::vector<P2> p(n);
  P2 lo{1e300, 1e300}, hi{-1e300, -1e300};
  for (std::size_t i = 0; i < n; ++i) {
    p[i] = {dot(outline[i], e1), dot(outline[i], e2)};
    lo = {std::min(lo.x, p[i].x), std::min(lo.y, p[i].y)};
    hi = {std::max(hi.x, p[i].x), std::max(hi.y, p[i].y)};
  }
  const double span = std::max({hi.x - lo.x, hi.y - lo.y, 1e-300});
  out.uvs.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    out.uvs[i] = {float((p[i].x - lo.x) / span), float((p[i].y - lo.y) / span)};
  }
  // Ear clipping (O(n^2), outlines are short): a convex corner whose triangle holds no other
  // remaining vertex is cut off, until three vertices are left.
  std::vector<std::uint32_t> ring(n);
  for (std::size_t i = 0; i < n; ++i) ring[i] = std::uint32_t(i);
  while (ring.size() > 3) {
    bool cut = false;
    for (std::size_t k = 0; k < ring.size() && !cut; ++k) {
      const std::uint32_t a = ring[(k + ring.size() - 1) % ring.size()], b = ring[k],
                          c = ring[(k + 1) % ring.size()];
      if (cross2(p[a], p[b], p[c]) <= 0) continue;  // reflex or flat corner
      bool empty = true;
      for (std::uint32_t v : ring) {
        if (v == a || v == b || v == c) continue;
        if (in_triangle(p[v], p[a], p[b], p[c])) {
          empty = false;
          break;
        }
      }
      if (!empty) continue;
      out.indices.insert(out.indices.end(), {a, b, c});
      ring.erase(ring.begin() + std::ptrdiff_t(k));
      cut = true;
    }
    if (!cut) break;  // self-overlapping in the plane: the rest as a fan
  }
  for (std::size_t k = 1; k + 1 < ring.size(); ++k) {
    out.indices.insert(out.indices.end(), {ring[0], ring[k], ring[k + 1]});
  }
  return out;
}

}  // namespace ramus::mesh
