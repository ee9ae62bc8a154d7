// The engine-ready instance buffer of a pieces forest: one little-endian binary file and a small
// JSON manifest beside it, laid out byte by byte in docs/instance-buffer.md. The binary holds
// what a renderer uploads (section 4.3 and 5.1 of Burkus et al.): the skinning matrix of every
// bone of every tree in one bone buffer, per instance its bone offset (added to the piece-local
// blend indices in the vertex shader) and the offset of its tile slices, the tile slices
// themselves, and per piece type the run of instances one instanced draw call draws.
#pragma once

#include <cstdint>
#include <string>

#include "backends/pieces/output_layout.h"
#include "backends/pieces/pieces.h"
#include "formats/pieces_instance_buffer.h"

namespace ramus::pieces {

// The binary's layout lives in formats/pieces_instance_buffer.h, shared with the expansion of
// an .rmb's placed-pieces stream; this file adds the forest's tables and the manifest.
using ramus::kBoneRecordBytes;
using ramus::kInstanceBufferHeaderBytes;
using ramus::kInstanceBufferMagic;
using ramus::kInstanceBufferVersion;
using ramus::kInstanceRecordBytes;

struct InstanceBufferBytes {
  std::string binary;
  std::string manifest;  // JSON, ends with a newline
};

// `binary_name` is the file name the manifest refers to; `meshes_name` (may be empty) the glTF
// file holding the piece meshes (a canonical or gpu-instancing output of the same forest).
InstanceBufferBytes encode_instance_buffer(const PieceSet& set, const Forest& forest,
                                           const std::string& binary_name,
                                           const std::string& meshes_name = "");

// Writes `path` (the binary) and the manifest beside it (same stem, .json) atomically; returns
// the manifest's path. Throws PiecesError for a forest beyond 32-bit offsets, WriteError when a
// file cannot be written.
std::string write_instance_buffer(const PieceSet& set, const Forest& forest,
                                  const std::string& path, const std::string& meshes_name = "");

}  // namespace ramus::pieces
