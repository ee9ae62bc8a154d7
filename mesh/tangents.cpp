#include "mesh/tangents.h"

#include <cmath>

#include "core/vec3.h"

namespace ramus::mesh {

std::vector<float> vertex_tangents(const std::vector<float>& positions,
                                   const std::vector<float>& normals, const std::vector<float>& uvs,
                                   const std::vector<std::uint32_t>& indices) {
  const std::size_t n = positions.size() / 3;
  auto p = [&](std::uint32_t i) {
    return Vec3{positions[3 * i], positions[3 * i + 1], positions[3 * i + 2]};
  };
  std::vector<Vec3> tu(n), tv(n);
  for (std::size_t i = 0; i + 2 < indices.size(); i += 3) {
    const std::uint32_t a = indices[i], b = indices[i + 1], c = indices[i + 2];
    const Vec3 e1 = p(b) - p(a), e2 = p(c) - p(a);
    const double du1 = uvs[2 * b] - uvs[2 * a], dv1 = uvs[2 * b + 1] - uvs[2 * a + 1];
    const double du2 = uvs[2 * c] - uvs[2 * a], dv2 = uvs[2 * c + 1] - uvs[2 * a + 1];
    const double det = du1 * dv2 - du2 * dv1;
    if (std::abs(det) < 1e-12) continue;
    const Vec3 su = (e1 * dv2 - e2 * dv1) / det, sv = (e2 * du1 - e1 * du2) / det;
    for (std::uint32_t v : {a, b, c}) {
      tu[v] += su;
      tv[v] += sv;
    }
  }
  std::vector<float> out(4 * n);
  for (std::size_t v = 0; v < n; ++v) {
    const Vec3 nrm = normalized(Vec3{normals[3 * v], normals[3 * v + 1], normals[3 * v + 2]});
    Vec3 t = tu[v] - nrm * dot(nrm, tu[v]);
    if (length(t) < 1e-9 * (1 + length(tu[v]))) {
      t = cross(nrm, std::abs(nrm.x) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0});
    }
    t = t / length(t);
    const double w = dot(cross(nrm, t), tv[v]) < 0 ? -1.0 : 1.0;
    out[4 * v] = float(t.x);
    out[4 * v + 1] = float(t.y);
    out[4 * v + 2] = float(t.z);
    out[4 * v + 3] = float(w);
  }
  return out;
}

}  // namespace ramus::mesh
