// The "laszip encoded" variable length record (user id "laszip encoded", record id 22204) that
// makes a LAS file a LAZ file: which compressor coded the points, in which chunks, and the list
// of items (point10, gpstime11, rgb12, point14, ...) each record is made of, with their versions.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace ramus::laz {

enum class ItemType : std::uint16_t {
  kByte = 0,
  kPoint10 = 6,
  kGpsTime11 = 7,
  kRgb12 = 8,
  kWavePacket13 = 9,
  kPoint14 = 10,
  kRgb14 = 11,
  kRgbNir14 = 12,
  kWavePacket14 = 13,
  kByte14 = 14,
};

struct Item {
  ItemType type;
  std::uint16_t size;
  std::uint16_t version;
};

inline constexpr std::uint16_t kCompressorPointwise = 1;
inline constexpr std::uint16_t kCompressorChunked = 2;
inline constexpr std::uint16_t kCompressorLayered = 3;
inline constexpr std::uint32_t kVariableChunkSize = 0xFFFFFFFFu;

struct LaszipVlr {
  std::uint16_t compressor = 0;
  std::uint16_t coder = 0;
  std::uint32_t chunk_size = 0;  // points per chunk; kVariableChunkSize: per-chunk counts
  std::vector<Item> items;
  std::size_t record_length() const;
};

// "point10 v2" etc.
std::string item_name(const Item& item);

// Parses the VLR's payload. On a malformed payload returns false and sets `why` and
// `error_at` (an offset into `payload`).
bool parse_laszip_vlr(std::string_view payload, LaszipVlr& out, std::string& why,
                      std::size_t& error_at);

}  // namespace ramus::laz
