// Context tables and helpers shared by the version 2 point10 decoder and encoder (Isenburg 2013,
// section 4.1): the return number r and return count n of a point select the context of its
// intensity and coordinate predictions, and the level |n - r| the context of its height.
#pragma once

#include <cstdint>
#include <cstring>

namespace ramus::laz {

// Context of each (n, r) pair: 0-14 for the 15 valid pairs with 1 <= r <= n <= 5, the
// remaining contexts shared by invalid or unusual combinations (files numbering returns from 0,
// swapping r and n, ...). This table is part of the format.
inline constexpr std::uint8_t kReturnContext[8][8] = {
    {15, 14, 13, 12, 11, 10, 9, 8},  {14, 0, 1, 3, 6, 10, 10, 9},
    {13, 1, 2, 4, 7, 11, 11, 10},    {12, 3, 4, 5, 8, 12, 12, 11},
    {11, 6, 7, 8, 9, 13, 13, 12},    {10, 10, 11, 12, 13, 14, 14, 13},
    {9, 10, 11, 12, 13, 14, 15, 14}, {8, 9, 10, 11, 12, 13, 14, 15}};

inline std::uint32_t return_level(std::uint32_t n, std::uint32_t r) {
  return n > r ? n - r : r - n;
}

// The median of the last five values, kept incrementally (LASzip's "streaming median").
class StreamingMedian5 {
 public:
  void reset() {
    for (auto& v : v_) v = 0;
    high_ = true;
  }
  std::int32_t get() const { return v_[2]; }
  void add(std::int32_t v);

 private:
  std::int32_t v_[5] = {0, 0, 0, 0, 0};
  bool high_ = true;
};

inline std::uint8_t fold_u8(std::int32_t n) { return std::uint8_t(n & 0xff); }
inline std::int32_t clamp_u8(std::int32_t n) { return n < 0 ? 0 : n > 255 ? 255 : n; }

template <typename T>
T get_le(const std::uint8_t* p) {
  T v;
  std::memcpy(&v, p, sizeof v);
  return v;
}
template <typename T>
void put_le(std::uint8_t* p, T v) {
  std::memcpy(p, &v, sizeof v);
}

}  // namespace ramus::laz
