// Triangulation of the turtle's polygons (ABOP 5.2, `{ . }`): planar and mildly non-planar
// outlines, convex or not, as recorded by the turtle.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "core/vec3.h"

namespace ramus::mesh {

struct PolygonTriangles {
  Vec3 normal;  // unit normal of the best-fit plane; triangles wind counter-clockwise about it
  std::vector<std::array<float, 2>> uvs;  // per outline vertex: its place in the plane, in [0,1]^2
  std::vector<std::uint32_t> indices;     // triangles over the outline's vertices
};

// Triangulates an outline (3 or more points, not closed) by ear clipping in its best-fit plane
// (Newell's normal, which averages a non-planar outline's twist). An outline that folds over
// itself in that plane, where no ear is left, is finished as a fan. Returns no triangles for an
// outline without area.
PolygonTriangles triangulate_polygon(const std::vector<Vec3>& outline);

}  // namespace ramus::mesh
