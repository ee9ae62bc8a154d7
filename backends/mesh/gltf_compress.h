// Compressed glTF: `ramus build --compress draco|meshopt`. A GLB as the writers make it (one
// buffer, tightly packed float, byte and short accessors, one set of accessors per primitive) is
// re-encoded: its triangle primitives' vertices and indices are compressed, everything else
// (images, inverse bind matrices, animation) is kept as it is. Settings in docs/mesh.md.
#pragma once

#include <string>

namespace ramus::mesh {

enum class GltfCompression {
  kNone,
  // KHR_draco_mesh_compression: positions 14 bits, normals 10, texture coordinates 12, _WIND
  // and WEIGHTS_0 8 (Draco's own quantization), joint indices lossless.
  kDraco,
  // EXT_meshopt_compression with KHR_mesh_quantization: vertices in cache-friendly order;
  // positions and texture coordinates float through the EXPONENTIAL filter (16 and 12 bits of
  // mantissa per vector), normals 8-bit
  // octahedral (OCTAHEDRAL filter), _WIND and WEIGHTS_0 normalized bytes.
  kMeshopt,
};

// The compressed GLB. Throws std::runtime_error for a GLB outside the layout above.
std::string compress_glb(const std::string& glb, GltfCompression how);

}  // namespace ramus::mesh
