// The container side of glTF, shared by every glTF writer and reader: a model serialized once as
// a GLB either stays a .glb, or becomes a .gltf whose one buffer lives in a .bin beside it; a GLB
// read from anyone is checked against the container's layout first.
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <string>

namespace ramus::mesh {

struct GltfBytes {
  std::string main;  // a GLB container, or the JSON of a .gltf
  std::string bin;   // the .bin of a .gltf (empty for a .glb)
};

// The JSON chunk of `glb` with its first buffer pointing at `bin_uri` (URI-escaped), followed by
// a newline: the text of a .gltf. nullopt when the JSON holds no buffer.
std::optional<std::string> gltf_json_with_buffer_uri(const std::string& glb,
                                                     const std::string& bin_uri);

// The binary chunk of a GLB ("" when it has none).
std::string glb_bin(const std::string& glb);

// Why `size` bytes are not a GLB container as glTF 2.0 lays it out ("Binary glTF Layout": a
// 12-byte header with the magic, version 2 and the total length, then chunks of a 4-byte-aligned
// length and a type, the first JSON, a BIN only second), as "byte N: what was expected"; "" when
// they are. Readers check this before tinygltf sees the bytes: Debian's tinygltf copies a BIN
// chunk by the length the file claims, past the end of a file that ends sooner.
std::string glb_layout_error(const unsigned char* data, std::size_t size);

// Writes `path` atomically: for .glb the bytes encode(true, "") gives; for .gltf the JSON of
// encode(false, "<stem>.bin") and that .bin beside it. Returns false, writing nothing, when
// `path` ends in neither (the caller reports it in its own error type).
bool write_gltf_files(
    const std::string& path,
    const std::function<GltfBytes(bool binary, const std::string& bin_uri)>& encode);

}  // namespace ramus::mesh
