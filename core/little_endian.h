// Appending numbers to a byte string in little-endian order, whatever the host's byte order:
// the binary PLY files ramus writes are little-endian.
#pragma once

#include <bit>
#include <cstring>
#include <string>
#include <utility>

namespace ramus {

template <typename T>
void append_little_endian(std::string& out, T v) {
  char b[sizeof(T)];
  std::memcpy(b, &v, sizeof(T));
  if constexpr (std::endian::native == std::endian::big) {
    for (std::size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(b[i], b[sizeof(T) - 1 - i]);
  }
  out.append(b, sizeof(T));
}

}  // namespace ramus
