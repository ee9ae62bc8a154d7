// Fuzz target for piece glTF files (backends/pieces/piece_file_gltf.cpp, docs/pieces.md): input
// that starts with the binary magic is read as .glb, anything else as .gltf (JSON).
#include <cstring>

#include "fuzz_piece_file_common.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const bool binary = size >= 4 && std::memcmp(data, "glTF", 4) == 0;
  return ramus::fuzz::read_piece_file_once(data, size, binary ? ".glb" : ".gltf");
}
