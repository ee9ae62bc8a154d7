// The inverse of laz_points.cpp: each chunk is its first record raw followed by one range-coded
// stream of the others; the chunk table lists every chunk's byte size, range coded as in the
// reader.
#include "formats/laz/laz_writer.h"

#include <algorithm>
#include <cstring>
#include <memory>
#include <vector>

#include "formats/laz/integer_encoder.h"
#include "formats/laz/item_encoders.h"
#include "formats/laz/layered_encoder.h"

namespace ramus::laz {
namespace {

template <typename T>
void append(std::string& s, T v) {
  char b[sizeof v];
  std::memcpy(b, &v, sizeof v);
  s.append(b, sizeof v);
}

}  // namespace

bool v2_items(unsigned format, std::size_t record_length, LaszipVlr& out,
              std::uint32_t chunk_size) {
  static constexpr std::size_t kSize[] = {20, 28, 26, 34};
  if (format >= 6 && format <= 8) {  // the layered coder
    static constexpr std::size_t kSize14[] = {30, 36, 38};
    if (record_length < kSize14[format - 6]) return false;
    out = {};
    out.compressor = kCompressorLayered;
    out.chunk_size = chunk_size;
    out.items.push_back({ItemType::kPoint14, 30, 3});
    if (format == 7) out.items.push_back({ItemType::kRgb14, 6, 3});
    if (format == 8) out.items.push_back({ItemType::kRgbNir14, 8, 3});
    const std::size_t extra = record_length - kSize14[format - 6];
    if (extra > 0) out.items.push_back({ItemType::kByte14, std::uint16_t(extra), 3});
    return true;
  }
  if (format > 3 || record_length < kSize[format]) return false;
  out = {};
  out.compressor = kCompressorChunked;
  out.chunk_size = chunk_size;
  out.items.push_back({ItemType::kPoint10, 20, 2});
  if (format == 1 || format == 3) out.items.push_back({ItemType::kGpsTime11, 8, 2});
  if (format >= 2) out.items.push_back({ItemType::kRgb12, 6, 2});
  const std::size_t extra = record_length - kSize[format];
  if (extra > 0) out.items.push_back({ItemType::kByte, std::uint16_t(extra), 2});
  return true;
}

std::string laszip_vlr_payload(const LaszipVlr& vlr) {
  std::string s;
  append<std::uint16_t>(s, vlr.compressor);
  append<std::uint16_t>(s, vlr.coder);
  append<std::uint8_t>(s, 2);  // LASzip version 2.2.0, whose items these are
  append<std::uint8_t>(s, 2);
  append<std::uint16_t>(s, 0);
  append<std::uint32_t>(s, 0);  // options
  append<std::uint32_t>(s, vlr.chunk_size);
  append<std::int64_t>(s, -1);  // no special EVLRs
  append<std::int64_t>(s, -1);
  append<std::uint16_t>(s, std::uint16_t(vlr.items.size()));
  for (const auto& item : vlr.items) {
    append<std::uint16_t>(s, std::uint16_t(item.type));
    append<std::uint16_t>(s, item.size);
    append<std::uint16_t>(s, item.version);
  }
  return s;
}

std::string compress_points(const LaszipVlr& vlr, const std::uint8_t* records, std::size_t count,
                            std::uint64_t block_offset,
                            const std::vector<std::uint32_t>& chunk_points) {
  const bool variable = vlr.chunk_size == kVariableChunkSize;
  std::vector<std::unique_ptr<ItemEncoder>> items;
  std::vector<std::size_t> sizes;
  for (const auto& item : vlr.items) {
    if (item.version == 2) items.push_back(make_v2_encoder(item));
    sizes.push_back(item.size);
  }
  const std::size_t record = vlr.record_length();
  std::vector<std::uint8_t> out(8);  // the chunk table offset, filled in at the end
  std::vector<std::uint32_t> chunk_bytes, chunk_counts;
  for (std::size_t first = 0, c = 0; first < count; first += chunk_counts.back(), ++c) {
    const std::size_t n =
        std::min<std::size_t>(variable ? chunk_points.at(c) : vlr.chunk_size, count - first);
    chunk_counts.push_back(std::uint32_t(n));
    const std::size_t start = out.size();
    const std::uint8_t* rec = records + first * record;
    if (vlr.compressor == kCompressorLayered) {
      encode_layered_chunk(vlr.items, rec, n, out);
      chunk_bytes.push_back(std::uint32_t(out.size() - start));
      continue;
    }
    out.insert(out.end(), rec, rec + record);
    std::size_t at = 0;
    for (std::size_t k = 0; k < items.size(); at += sizes[k++]) items[k]->init(rec + at);
    RangeEncoder enc(out);
    for (std::size_t i = 1; i < n; ++i) {
      rec += record;
      at = 0;
      for (std::size_t k = 0; k < items.size(); at += sizes[k++]) items[k]->encode(enc, rec + at);
    }
    enc.finish();
    chunk_bytes.push_back(std::uint32_t(out.size() - start));
  }
  const std::int64_t table = std::int64_t(block_offset + out.size());
  std::memcpy(out.data(), &table, 8);
  std::string s(out.begin(), out.end());
  append<std::uint32_t>(s, 0);  // chunk table version
  append<std::uint32_t>(s, std::uint32_t(chunk_bytes.size()));
  std::vector<std::uint8_t> coded;
  RangeEncoder enc(coded);
  IntegerEncoder ic(32, 2);
  std::int32_t prev_points = 0, prev_bytes = 0;
  for (std::size_t i = 0; i < chunk_bytes.size(); ++i) {
    if (variable) {
      ic.encode(enc, prev_points, std::int32_t(chunk_counts[i]), 0);
      prev_points = std::int32_t(chunk_counts[i]);
    }
    ic.encode(enc, prev_bytes, std::int32_t(chunk_bytes[i]), 1);
    prev_bytes = std::int32_t(chunk_bytes[i]);
  }
  enc.finish();
  s.append(coded.begin(), coded.end());
  return s;
}

}  // namespace ramus::laz
