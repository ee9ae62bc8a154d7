// Fuzz target for piece OBJ files (backends/pieces/piece_file_obj.cpp, docs/pieces.md).
#include "fuzz_piece_file_common.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return ramus::fuzz::read_piece_file_once(data, size, ".obj");
}
