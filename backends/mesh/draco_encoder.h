// Draco compression of one triangle primitive (Google's Draco, Debian libdraco-dev), for glTF's
// KHR_draco_mesh_compression. The one file that includes Draco's headers is draco_encoder.cpp.
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace ramus::mesh {

enum class DracoKind { kPosition, kNormal, kTexCoord, kGeneric };

// One vertex attribute, tightly packed: count * components values of 4-byte floats
// (component_bytes 4, is_float) or unsigned integers of 1 or 2 bytes.
struct DracoAttribute {
  std::string name;  // the glTF attribute name (POSITION, _WIND, JOINTS_0, ...)
  DracoKind kind = DracoKind::kGeneric;
  int components = 3;
  bool is_float = true;
  int component_bytes = 4;
  std::vector<unsigned char> data;
  int quantization_bits = 0;  // floats only; 0 keeps them lossless
};

struct DracoPrimitive {
  std::string bytes;                        // the Draco bitstream
  std::map<std::string, int> attribute_id;  // glTF name -> Draco unique id
  std::size_t points = 0, faces = 0;        // what the decoder gives back
};

// Encodes the triangles `indices` over `count` vertices with the given attributes. Edgebreaker
// may reorder (and so renumber) the vertices: the glTF accessors take `points` and 3 * `faces`.
// Throws std::runtime_error when Draco refuses the mesh.
DracoPrimitive draco_encode(const std::vector<DracoAttribute>& attributes, std::size_t count,
                            const std::vector<std::uint32_t>& indices);

}  // namespace ramus::mesh
