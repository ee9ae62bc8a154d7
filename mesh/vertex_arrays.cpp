#include "mesh/vertex_arrays.h"

#include "mesh/tangents.h"

namespace ramus::mesh {

VertexArrays vertex_arrays(const MeshPart& part, UpAxis up, bool tangents) {
  VertexArrays out;
  const std::size_t n = part.vertex_count();
  out.positions.reserve(3 * n);
  out.normals.reserve(3 * n);
  auto append = [up](std::vector<float>& to, Vec3f v) {
    if (up == UpAxis::kY) v = z_up_to_y_up(v);
    to.insert(to.end(), {v.x, v.y, v.z});
  };
  for (std::size_t i = 0; i < n; ++i) {
    append(out.positions, part.positions[i]);
    append(out.normals, part.normals[i]);
  }
  if (tangents) {
    const float* uv = reinterpret_cast<const float*>(part.uvs.data());
    out.tangents = vertex_tangents(out.positions, out.normals,
                                   std::vector<float>(uv, uv + 2 * part.uvs.size()), part.indices);
  }
  return out;
}

}  // namespace ramus::mesh
