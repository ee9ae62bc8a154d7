// The body of the piece file fuzz targets (fuzz_piece_obj.cpp, fuzz_piece_gltf.cpp): the piece
// readers take a path (a piece file may name its buffers beside it), so the input is written to
// a file of this process's own folder in /tmp and read from there. Any input either gives a piece
// draft, which must then finish into a piece type (joints, normals, tiles, levels of detail), or
// raises PiecesError.
#pragma once

#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "backends/pieces/piece_build.h"

namespace ramus::fuzz {

inline int read_piece_file_once(const std::uint8_t* data, std::size_t size, const char* ext) {
  static const std::filesystem::path dir = [] {
    std::filesystem::path d =
        std::filesystem::temp_directory_path() / ("ramus-fuzz-piece-" + std::to_string(::getpid()));
    std::filesystem::create_directories(d);
    return d;
  }();
  const std::filesystem::path file = dir / (std::string("piece") + ext);
  {
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), std::streamsize(size));
    if (!out) std::abort();  // the fuzzer's own disk, not the input: stop loudly
  }
  try {
    pieces::PieceDraft draft = pieces::draft_mesh_file("fuzz", file.string());
    pieces::PieceType type = pieces::finish_piece(std::move(draft), {1, 2});
    if (type.lods.empty()) std::abort();
  } catch (const pieces::PiecesError&) {
  }
  return 0;
}

}  // namespace ramus::fuzz
