// Invariants every TreeMesh must satisfy, shared by the mesh tests. Each returns an empty string
// when the invariant holds, else a description of the first violation.
#pragma once

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <string>
#include <tuple>
#include <vector>

#include "mesh/tree_mesh.h"

namespace ramus::testing {

inline std::string check_finite_and_unit(const mesh::MeshPart& p) {
  if (p.normals.size() != p.positions.size() || p.uvs.size() != p.positions.size() ||
      p.wind.size() != p.positions.size()) {
    return "attribute arrays differ in length";
  }
  for (std::size_t i = 0; i < p.positions.size(); ++i) {
    if (!is_finite(p.positions[i]) || !is_finite(p.normals[i]))
      return "non-finite vertex " + std::to_string(i);
    if (std::abs(length(p.normals[i]) - 1.0f) > 1e-4f)
      return "normal not unit at " + std::to_string(i);
    for (float w : p.wind[i]) {
      if (!(w >= 0.0f && w <= 1.0f)) return "wind weight outside [0,1] at " + std::to_string(i);
    }
    if (!std::isfinite(p.uvs[i][0]) || !std::isfinite(p.uvs[i][1])) return "non-finite uv";
  }
  for (std::uint32_t k : p.indices) {
    if (k >= p.positions.size()) return "index out of range";
  }
  return {};
}

inline double triangle_area(const mesh::MeshPart& p, std::size_t t) {
  const Vec3 a(p.positions[p.indices[3 * t]]), b(p.positions[p.indices[3 * t + 1]]),
      c(p.positions[p.indices[3 * t + 2]]);
  return 0.5 * length(cross(b - a, c - a));
}

inline std::string check_no_degenerate(const mesh::MeshPart& p, double min_area) {
  for (std::size_t t = 0; t < p.triangle_count(); ++t) {
    if (!(triangle_area(p, t) > min_area)) return "degenerate triangle " + std::to_string(t);
  }
  return {};
}

// Vertex normals agree with the winding (counter-clockwise seen from outside).
inline std::string check_winding_matches_normals(const mesh::MeshPart& p) {
  for (std::size_t t = 0; t < p.triangle_count(); ++t) {
    const std::uint32_t* i = &p.indices[3 * t];
    const Vec3 a(p.positions[i[0]]), b(p.positions[i[1]]), c(p.positions[i[2]]);
    const Vec3 fn = cross(b - a, c - a);
    const Vec3 vn = Vec3(p.normals[i[0]]) + Vec3(p.normals[i[1]]) + Vec3(p.normals[i[2]]);
    if (dot(fn, vn) <= 0) return "triangle " + std::to_string(t) + " faces against its normals";
  }
  return {};
}

// Welds vertices by exact position, splits the triangles into edge-connected components and
// checks each is closed and consistently oriented (every edge used exactly twice, once in each
// direction) with positive signed volume (normals point outward). `components` gets the count.
inline std::string check_closed_tubes(const mesh::MeshPart& p, std::size_t* components = nullptr) {
  std::map<std::tuple<float, float, float>, std::uint32_t> weld;
  std::vector<std::uint32_t> id(p.positions.size());
  for (std::size_t i = 0; i < p.positions.size(); ++i) {
    const auto key = std::make_tuple(p.positions[i].x, p.positions[i].y, p.positions[i].z);
    id[i] = weld.emplace(key, std::uint32_t(weld.size())).first->second;
  }
  const std::size_t nt = p.triangle_count();
  std::vector<std::size_t> parent(nt);
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](std::size_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<std::size_t>> directed;
  for (std::size_t t = 0; t < nt; ++t) {
    for (int e = 0; e < 3; ++e) {
      const std::uint32_t a = id[p.indices[3 * t + e]], b = id[p.indices[3 * t + (e + 1) % 3]];
      directed[{a, b}].push_back(t);
    }
  }
  for (const auto& [edge, tris] : directed) {
    if (tris.size() != 1) return "edge used twice in the same direction";
    auto it = directed.find({edge.second, edge.first});
    if (it == directed.end()) return "open edge (a hole) in a tube";
    parent[find(tris[0])] = find(it->second[0]);
  }
  std::map<std::size_t, double> volume;
  for (std::size_t t = 0; t < nt; ++t) {
    const std::uint32_t* i = &p.indices[3 * t];
    const Vec3 a(p.positions[i[0]]), b(p.positions[i[1]]), c(p.positions[i[2]]);
    volume[find(t)] += dot(a, cross(b, c)) / 6.0;  // divergence theorem
  }
  for (const auto& [root, v] : volume) {
    if (!(v > 0)) return "a closed tube has non-positive volume (normals point inward)";
  }
  if (components) *components = volume.size();
  return {};
}

}  // namespace ramus::testing
