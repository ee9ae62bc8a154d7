// Per-vertex tangents for normal-mapped glTF primitives (the TANGENT attribute): glTF asks for
// them with a normal map rather than leaving each viewer to derive its own (the validator warns
// MESH_PRIMITIVE_GENERATED_TANGENT_SPACE otherwise).
#pragma once

#include <cstdint>
#include <vector>

namespace ramus::mesh {

// `positions` and `normals` hold 3 floats per vertex, `uvs` 2, `indices` triangles. Returns 4
// floats per vertex: xyz the unit direction in which u grows (each triangle's UV gradient summed
// over the triangles at the vertex, made orthogonal to the normal; any direction across the
// normal where u does not vary), w = +-1 the handedness of (normal, tangent, direction of v).
std::vector<float> vertex_tangents(const std::vector<float>& positions,
                                   const std::vector<float>& normals, const std::vector<float>& uvs,
                                   const std::vector<std::uint32_t>& indices);

}  // namespace ramus::mesh
