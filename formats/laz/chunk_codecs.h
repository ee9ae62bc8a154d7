// How one chunk's bytes become records: the pointwise chunks of compressor 2 (first record raw,
// then one range-coded stream for all items of all points) and the layered chunks of compressor
// 3 (first record raw, then separately coded layers per field group, LAS 1.4 formats 6-8).
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>

#include "formats/laz/laszip_vlr.h"

namespace ramus::laz {

class ChunkCodec {
 public:
  virtual ~ChunkCodec() = default;
  // Starts a chunk of `points` records held in [begin, end).
  virtual void start(const std::uint8_t* begin, const std::uint8_t* end, std::size_t points) = 0;
  // Decodes the chunk's next record into `out`; throws StreamOverrun when the bytes run out.
  virtual void next(std::uint8_t* out) = 0;
};

// The codec for the VLR's compressor and items; nullptr with `why` set when this reader cannot
// decode them.
std::unique_ptr<ChunkCodec> make_chunk_codec(const LaszipVlr& vlr, std::string& why);

}  // namespace ramus::laz
