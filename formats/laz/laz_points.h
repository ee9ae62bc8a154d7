// Decompresses the point records of a LAZ file (LAS with a "laszip encoded" VLR) chunk by
// chunk: reads the chunk table, checks it against the header's point count and the file's
// size, and hands each chunk's decoded records to a sink before decoding the next, so at most
// one chunk of uncompressed records is held at a time. Malformed input (a bad chunk table, cut
// off or corrupt chunks, counts that disagree) raises a FormatError with the byte offset.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>

namespace ramus::laz {

struct LazInput {
  std::string_view file;        // the whole file
  std::string name;             // for messages
  std::size_t vlr_payload = 0;  // byte offset of the laszip VLR's payload
  std::size_t vlr_length = 0;   // its length
  std::size_t point_offset = 0;
  std::uint64_t count = 0;  // points the header announces
  unsigned format = 0;      // point data record format (compression bits cleared)
  std::size_t record_length = 0;
  // Called after each chunk with the byte offset just past it (may be empty).
  std::function<void(std::size_t)> release = {};
};

// Receives `n` records of `record_length` bytes each, the first being point `first`.
using RecordSink =
    std::function<void(const std::uint8_t* records, std::size_t n, std::uint64_t first)>;

// "chunked (compressor 2), point10 v2 + gpstime11 v2, 50000-point chunks" for reports.
std::string describe_laz(const LazInput& in);

void decode_laz_points(const LazInput& in, const RecordSink& sink);

}  // namespace ramus::laz
