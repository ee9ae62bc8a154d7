#include "formats/laz/point14_context.h"

#include <cstring>

namespace ramus::laz {

Point14 Point14::unpack(const std::uint8_t* b) {
  Point14 p;
  p.x = get_le<std::int32_t>(b);
  p.y = get_le<std::int32_t>(b + 4);
  p.z = get_le<std::int32_t>(b + 8);
  p.intensity = get_le<std::uint16_t>(b + 12);
  p.r = b[14] & 15;
  p.n = b[14] >> 4;
  p.flags =
      std::uint8_t((b[15] & 15) | ((b[15] >> 2) & 0x30));  // edge << 5 | dir << 4 | class flags
  p.channel = (b[15] >> 4) & 3;
  p.cls = b[16];
  p.user = b[17];
  p.angle = get_le<std::int16_t>(b + 18);
  p.source = get_le<std::uint16_t>(b + 20);
  p.gps = get_le<std::uint64_t>(b + 22);
  return p;
}

void Point14::pack(std::uint8_t* b) const {
  put_le(b, x);
  put_le(b + 4, y);
  put_le(b + 8, z);
  put_le(b + 12, intensity);
  b[14] = std::uint8_t(r | (n << 4));
  b[15] = std::uint8_t((flags & 15) | (channel << 4) | ((flags & 0x30) << 2));
  b[16] = cls;
  b[17] = user;
  put_le(b + 18, angle);
  put_le(b + 20, source);
  put_le(b + 22, gps);
}

std::uint32_t return_context6(std::uint32_t n, std::uint32_t r) {
  // Part of the format (LASzip's number_return_map_6ctx): single, first, last, intermediate
  // returns of few and of many returns.
  static constexpr std::uint8_t kMap[16][16] = {{0, 1, 2, 3, 4, 5, 3, 4, 4, 5, 5, 5, 5, 5, 5, 5},
                                                {1, 0, 1, 3, 3, 3, 3, 3, 3, 3, 3, 3, 3, 3, 3, 3},
                                                {2, 1, 2, 4, 4, 4, 4, 4, 4, 4, 4, 3, 3, 3, 3, 3},
                                                {3, 3, 4, 5, 4, 4, 4, 4, 4, 4, 4, 4, 4, 4, 4, 4},
                                                {4, 3, 4, 4, 5, 4, 4, 4, 4, 4, 4, 4, 4, 4, 4, 4},
                                                {5, 3, 4, 4, 4, 5, 4, 4, 4, 4, 4, 4, 4, 4, 4, 4},
                                                {3, 3, 4, 4, 4, 4, 5, 4, 4, 4, 4, 4, 4, 4, 4, 4},
                                                {4, 3, 4, 4, 4, 4, 4, 5, 4, 4, 4, 4, 4, 4, 4, 4},
                                                {4, 3, 4, 4, 4, 4, 4, 4, 5, 4, 4, 4, 4, 4, 4, 4},
                                                {5, 3, 4, 4, 4, 4, 4, 4, 4, 5, 4, 4, 4, 4, 4, 4},
                                                {5, 3, 4, 4, 4, 4, 4, 4, 4, 4, 5, 4, 4, 4, 4, 4},
                                                {5, 3, 3, 4, 4, 4, 4, 4, 4, 4, 4, 5, 5, 4, 4, 4},
                                                {5, 3, 3, 4, 4, 4, 4, 4, 4, 4, 4, 5, 5, 5, 4, 4},
                                                {5, 3, 3, 4, 4, 4, 4, 4, 4, 4, 4, 4, 5, 5, 5, 4},
                                                {5, 3, 3, 4, 4, 4, 4, 4, 4, 4, 4, 4, 4, 5, 5, 5},
                                                {5, 3, 3, 4, 4, 4, 4, 4, 4, 4, 4, 4, 4, 4, 5, 5}};
  return kMap[n & 15][r & 15];
}

}  // namespace ramus::laz
