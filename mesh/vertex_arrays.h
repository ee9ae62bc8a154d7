// The vertex arrays of a MeshPart as a consumer draws them: flat floats in glTF's y-up frame or in
// ramus's own z up, with tangents for a normal-mapped part. The glTF writer
// (backends/mesh/gltf_writer.cpp) writes exactly these arrays as its POSITION, NORMAL and TANGENT
// accessors and the embeddable runtime (runtime/ramus_mesher.cpp) hands out the same ones, so a
// tree meshed on the client has the bytes of the `.glb` that `ramus build` writes.
#pragma once

#include <vector>

#include "mesh/tree_mesh.h"
#include "core/up_axis.h"

namespace ramus::mesh {

struct VertexArrays {
  std::vector<float> positions;  // 3 per vertex
  std::vector<float> normals;    // 3 per vertex
  std::vector<float> tangents;   // 4 per vertex (tangents.h), or empty when not asked for
};

// Positions and normals of `part` in the `up` frame (z_up_to_y_up for kY: a permutation and sign
// change of the floats, nothing rounded again); with `tangents`, the TANGENT attribute computed
// in that frame from them, the UVs and the triangles.
VertexArrays vertex_arrays(const MeshPart& part, UpAxis up, bool tangents);

}  // namespace ramus::mesh
