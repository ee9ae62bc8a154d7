// LAZ writing with the version 2 items (point formats 0-3, plus extra bytes) and the layered
// point14 item (point format 6): the laszip VLR
// payload and the compressed point block (chunk table offset, chunks of 50,000 points, chunk
// table) that replace the raw records of a LAS file.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "formats/laz/laszip_vlr.h"

namespace ramus::laz {

inline constexpr std::uint32_t kDefaultChunkSize = 50000;

// The items of point format 0-3 records of `record_length` bytes (the rest extra bytes; LASzip
// 2 pointwise chunks), or of point format 6 records of 30 bytes (point14 v3, layered chunks).
// Returns false for formats this writer cannot compress.
bool v2_items(unsigned format, std::size_t record_length, LaszipVlr& out,
              std::uint32_t chunk_size = kDefaultChunkSize);

std::string laszip_vlr_payload(const LaszipVlr& vlr);

// The point block for `count` records starting at file offset `block_offset` (the LAS header's
// offset to point data). `vlr` must come from v2_items. With vlr.chunk_size ==
// kVariableChunkSize, `chunk_points` gives each chunk's point count (they must add up to count).
std::string compress_points(const LaszipVlr& vlr, const std::uint8_t* records, std::size_t count,
                            std::uint64_t block_offset,
                            const std::vector<std::uint32_t>& chunk_points = {});

}  // namespace ramus::laz
