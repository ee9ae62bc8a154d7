// Layout of a chunked LAZ point block (LASzip 2+, compressors 2 and 3): at the point data
// offset an i64 with the byte offset of the chunk table (-1 when the writer could not seek back:
// then the file's last 8 bytes hold it), then the chunks back to back, then the chunk table:
// u32 version (0), u32 chunk count, and the range-coded list of each chunk's point count (only
// for variable chunk sizes) and byte size, each predicted from the previous chunk's.
#include "formats/laz/laz_points.h"

#include <algorithm>
#include <cstring>
#include <memory>
#include <vector>

#include "formats/detail/reader_util.h"
#include "formats/laz/chunk_codecs.h"
#include "formats/laz/integer_decoder.h"
#include "formats/laz/laszip_vlr.h"

namespace ramus::laz {

using formats_detail::fail_at_byte;

namespace {

constexpr std::uint64_t kMaxPointsPerByte = 1024;

struct Chunk {
  std::uint64_t points = 0;
  std::uint64_t start = 0, bytes = 0;
};

LaszipVlr parse_vlr(const LazInput& in) {
  LaszipVlr vlr;
  std::string why;
  std::size_t at = 0;
  if (!parse_laszip_vlr(in.file.substr(in.vlr_payload, in.vlr_length), vlr, why, at)) {
    fail_at_byte(in.name, in.vlr_payload + at, why);
  }
  if (vlr.compressor == kCompressorPointwise) {
    fail_at_byte(in.name, in.vlr_payload,
                 "LAZ compressor 1 (pointwise, without chunks, from LASzip before 2.0) is not "
                 "supported; re-compress the file with a current LASzip");
  }
  if (vlr.record_length() != in.record_length) {
    fail_at_byte(in.name, in.vlr_payload + 32,
                 "the laszip record's items add up to " + std::to_string(vlr.record_length()) +
                     "-byte records but the header says " + std::to_string(in.record_length));
  }
  return vlr;
}

std::string item_list(const LaszipVlr& vlr) {
  std::string s;
  for (const auto& item : vlr.items) s += (s.empty() ? "" : " + ") + item_name(item);
  return s;
}

// Reads and checks the chunk table; the chunks' points add up to `in.count`.
std::vector<Chunk> read_chunk_table(const LazInput& in, const LaszipVlr& vlr) {
  const std::string_view f = in.file;
  const std::size_t data_start = in.point_offset + 8;
  if (in.count == 0) return {};
  if (f.size() < data_start) {
    fail_at_byte(
        in.name, f.size(),
        "the file ends before the chunk table offset at byte " + std::to_string(in.point_offset));
  }
  std::size_t where = in.point_offset;
  std::int64_t table = formats_detail::load_le<std::int64_t>(f.data() + where);
  if (table == -1 && f.size() >= data_start + 8) {
    where = f.size() - 8;  // written at the end by a writer that could not seek back
    table = formats_detail::load_le<std::int64_t>(f.data() + where);
  }
  if (table < std::int64_t(data_start) || std::uint64_t(table) + 8 > f.size()) {
    fail_at_byte(in.name, where,
                 "the chunk table offset " + std::to_string(table) +
                     " is outside the compressed points (bytes " + std::to_string(data_start) +
                     " to " + std::to_string(f.size()) + "): the file is cut off or corrupt");
  }
  const std::size_t t = std::size_t(table);
  const std::uint32_t version = formats_detail::load_le<std::uint32_t>(f.data() + t);
  const std::uint32_t n = formats_detail::load_le<std::uint32_t>(f.data() + t + 4);
  if (version != 0) {
    fail_at_byte(in.name, t,
                 "unknown chunk table version " + std::to_string(version) + " (expected 0)");
  }
  const bool variable = vlr.chunk_size == kVariableChunkSize;
  if (!variable) {
    const std::uint64_t expected = (in.count + vlr.chunk_size - 1) / vlr.chunk_size;
    if (n != expected) {
      fail_at_byte(in.name, t + 4,
                   "the chunk table lists " + std::to_string(n) + " chunks but the header's " +
                       std::to_string(in.count) + " points in chunks of " +
                       std::to_string(vlr.chunk_size) + " make " + std::to_string(expected));
    }
  } else if (n == 0 || n > in.count || n > f.size()) {
    fail_at_byte(in.name, t + 4,
                 "the chunk table lists " + std::to_string(n) + " chunks for " +
                     std::to_string(in.count) + " points");
  }
  // Every chunk starts with a raw record, so the table cannot list more chunks than fit.
  if (std::uint64_t(n) > (t - data_start) / in.record_length + 1) {
    fail_at_byte(in.name, t + 4,
                 "the chunk table lists " + std::to_string(n) + " chunks but only " +
                     std::to_string(t - data_start) + " bytes of compressed points precede it");
  }
  std::vector<Chunk> chunks(n);
  RangeDecoder dec;
  IntegerDecoder ic(32, 2);
  const auto* bytes = reinterpret_cast<const std::uint8_t*>(f.data());
  try {
    dec.start(bytes + t + 8, bytes + f.size());
    std::int32_t prev_points = 0, prev_bytes = 0;
    for (std::uint32_t i = 0; i < n; ++i) {
      if (variable) prev_points = ic.decode(dec, prev_points, 0);
      prev_bytes = ic.decode(dec, prev_bytes, 1);
      chunks[i].points = variable ? std::uint32_t(prev_points) : vlr.chunk_size;
      chunks[i].bytes = std::uint32_t(prev_bytes);
    }
  } catch (const StreamOverrun&) {
    fail_at_byte(in.name, f.size(), "the chunk table is cut off: the file ends inside it");
  }
  std::uint64_t start = data_start, points = 0;
  for (std::uint32_t i = 0; i < n; ++i) {
    chunks[i].start = start;
    start += chunks[i].bytes;
    if (start > t) {
      fail_at_byte(in.name, chunks[i].start,
                   "chunk " + std::to_string(i + 1) + " of " + std::to_string(n) + " (" +
                       std::to_string(chunks[i].bytes) +
                       " bytes by the chunk table) runs past the chunk table at byte " +
                       std::to_string(t));
    }
    if (!variable && i + 1 == n) chunks[i].points = in.count - points;
    if (variable && (chunks[i].points == 0 || chunks[i].points > in.count - points)) {
      fail_at_byte(in.name, t,
                   "the chunk table gives chunk " + std::to_string(i + 1) + " " +
                       std::to_string(chunks[i].points) + " points, more than the " +
                       std::to_string(in.count - points) + " the header has left");
    }
    // A corrupt count would make us decode garbage for as long as the stream does not run dry
    // (a zero-filled chunk hardly ever does): no real chunk compresses better than a few
    // hundred points per byte even when every point is the same.
    if (chunks[i].points > kMaxPointsPerByte * (chunks[i].bytes + 1)) {
      fail_at_byte(in.name, chunks[i].start,
                   "chunk " + std::to_string(i + 1) + " of " + std::to_string(n) + " would hold " +
                       std::to_string(chunks[i].points) + " points in " +
                       std::to_string(chunks[i].bytes) + " bytes (more than " +
                       std::to_string(kMaxPointsPerByte) +
                       " per byte): the point count or the chunk table is corrupt");
    }
    points += chunks[i].points;
  }
  if (points != in.count) {
    fail_at_byte(in.name, t,
                 "the chunk table's chunks hold " + std::to_string(points) +
                     " points but the header announces " + std::to_string(in.count));
  }
  return chunks;
}

}  // namespace

std::string describe_laz(const LazInput& in) {
  const LaszipVlr vlr = parse_vlr(in);
  std::string s = vlr.compressor == kCompressorLayered ? "layered chunks (compressor 3), "
                                                       : "chunks (compressor 2), ";
  s += item_list(vlr);
  if (vlr.chunk_size == kVariableChunkSize) return s + ", variable chunk sizes";
  return s + ", " + std::to_string(vlr.chunk_size) + "-point chunks";
}

void decode_laz_points(const LazInput& in, const RecordSink& sink) {
  const LaszipVlr vlr = parse_vlr(in);
  std::string why;
  std::unique_ptr<ChunkCodec> codec = make_chunk_codec(vlr, why);
  if (!codec) fail_at_byte(in.name, in.vlr_payload, why + " (items: " + item_list(vlr) + ")");
  const std::vector<Chunk> chunks = read_chunk_table(in, vlr);
  // Records go to the sink in batches, so memory stays bounded whatever a chunk claims.
  constexpr std::size_t kBatch = 4096;
  std::vector<std::uint8_t> records(kBatch * in.record_length);
  const auto* bytes = reinterpret_cast<const std::uint8_t*>(in.file.data());
  std::uint64_t first = 0;
  for (std::size_t i = 0; i < chunks.size(); ++i) {
    const Chunk& c = chunks[i];
    codec->start(bytes + c.start, bytes + c.start + c.bytes, std::size_t(c.points));
    std::uint64_t done = 0;
    try {
      while (done < c.points) {
        const std::size_t n = std::size_t(std::min<std::uint64_t>(kBatch, c.points - done));
        for (std::size_t k = 0; k < n; ++k, ++done) {
          codec->next(records.data() + k * in.record_length);
        }
        sink(records.data(), n, first);
        first += n;
      }
    } catch (const StreamOverrun&) {
      fail_at_byte(in.name, c.start + c.bytes,
                   "chunk " + std::to_string(i + 1) + " of " + std::to_string(chunks.size()) +
                       " (bytes " + std::to_string(c.start) + " to " +
                       std::to_string(c.start + c.bytes) + ") ends after " + std::to_string(done) +
                       " of its " + std::to_string(c.points) +
                       " points: its compressed data is cut off or corrupt");
    }
    if (in.release) in.release(std::size_t(c.start + c.bytes));
  }
}

}  // namespace ramus::laz
