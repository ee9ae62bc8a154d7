// Payload layout (little endian): u16 compressor, u16 coder, u8 version major, u8 minor,
// u16 revision, u32 options, u32 chunk size, i64 number of special EVLRs, i64 their offset,
// u16 item count, then per item u16 type, u16 size, u16 version: 34 + 6 n bytes.
#include "formats/laz/laszip_vlr.h"

#include <cstring>

namespace ramus::laz {
namespace {

template <typename T>
T le(std::string_view b, std::size_t at) {
  T v;
  std::memcpy(&v, b.data() + at, sizeof v);
  return v;
}

}  // namespace

std::size_t LaszipVlr::record_length() const {
  std::size_t n = 0;
  for (const auto& i : items) n += i.size;
  return n;
}

std::string item_name(const Item& item) {
  const char* name = "unknown item";
  switch (item.type) {
    case ItemType::kByte:
      name = "extra bytes";
      break;
    case ItemType::kPoint10:
      name = "point10";
      break;
    case ItemType::kGpsTime11:
      name = "gpstime11";
      break;
    case ItemType::kRgb12:
      name = "rgb12";
      break;
    case ItemType::kWavePacket13:
      name = "wavepacket13";
      break;
    case ItemType::kPoint14:
      name = "point14";
      break;
    case ItemType::kRgb14:
      name = "rgb14";
      break;
    case ItemType::kRgbNir14:
      name = "rgbnir14";
      break;
    case ItemType::kWavePacket14:
      name = "wavepacket14";
      break;
    case ItemType::kByte14:
      name = "extra bytes14";
      break;
  }
  std::string s = name;
  if (std::strcmp(name, "unknown item") == 0) s += " type " + std::to_string(unsigned(item.type));
  return s + " v" + std::to_string(item.version);
}

bool parse_laszip_vlr(std::string_view b, LaszipVlr& out, std::string& why, std::size_t& error_at) {
  if (b.size() < 34) {
    why = "the laszip record has " + std::to_string(b.size()) + " bytes, expected at least 34";
    error_at = 0;
    return false;
  }
  out.compressor = le<std::uint16_t>(b, 0);
  out.coder = le<std::uint16_t>(b, 2);
  out.chunk_size = le<std::uint32_t>(b, 12);
  const std::uint16_t count = le<std::uint16_t>(b, 32);
  if (b.size() < 34 + 6 * std::size_t(count)) {
    why = "the laszip record lists " + std::to_string(count) + " items (" +
          std::to_string(34 + 6 * count) + " bytes) but has " + std::to_string(b.size()) + " bytes";
    error_at = 32;
    return false;
  }
  if (count == 0) {
    why = "the laszip record lists no items";
    error_at = 32;
    return false;
  }
  out.items.clear();
  for (std::size_t i = 0; i < count; ++i) {
    const std::size_t at = 34 + 6 * i;
    out.items.push_back({ItemType(le<std::uint16_t>(b, at)), le<std::uint16_t>(b, at + 2),
                         le<std::uint16_t>(b, at + 4)});
  }
  if (out.coder != 0) {
    why = "unknown LAZ entropy coder " + std::to_string(out.coder) + " (expected 0, arithmetic)";
    error_at = 2;
    return false;
  }
  if (out.compressor < kCompressorPointwise || out.compressor > kCompressorLayered) {
    why = "unknown LAZ compressor " + std::to_string(out.compressor) +
          " (expected 1 pointwise, 2 chunked or 3 layered chunked)";
    error_at = 0;
    return false;
  }
  if (out.chunk_size == 0) {
    why = "the laszip record gives a chunk size of 0 points";
    error_at = 12;
    return false;
  }
  return true;
}

}  // namespace ramus::laz
