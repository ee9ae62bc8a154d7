// The range decoder of LAZ streams (Said's FastAC as adapted by LASzip): 32-bit interval,
// byte-wise renormalisation, symbols and bits through adaptive models, raw bits/shorts/ints.
// Reading past the end of its byte range throws StreamOverrun, which the LAZ reader turns into
// a positioned FormatError: a corrupt stream can never read outside its chunk.
#pragma once

#include <cstddef>
#include <cstdint>

#include "formats/laz/adaptive_models.h"

namespace ramus::laz {

// Thrown when a compressed stream needs bytes past its end (a truncated or corrupt chunk).
struct StreamOverrun {};

class RangeDecoder {
 public:
  // Starts decoding the bytes [begin, end): reads the first four bytes of the code value.
  void start(const std::uint8_t* begin, const std::uint8_t* end) {
    next_ = begin;
    end_ = end;
    length_ = kMaxLength;
    value_ = 0;
    for (int i = 0; i < 4; ++i) value_ = (value_ << 8) | byte();
  }
  // Bytes consumed so far (for checks that a stream ended where it should).
  const std::uint8_t* position() const { return next_; }

  std::uint32_t decode_bit(BitModel& m) {
    const std::uint32_t x = m.p0() * (length_ >> kBitShift);
    const bool one = value_ >= x;
    if (!one) {
      length_ = x;
    } else {
      value_ -= x;
      length_ -= x;
    }
    if (length_ < kMinLength) renormalise();
    m.count(one);
    return one;
  }

  std::uint32_t decode_symbol(SymbolModel& m) {
    std::uint32_t sym, x, y = length_;
    if (const std::uint32_t* table = m.table()) {
      length_ >>= kSymbolShift;
      const std::uint32_t dv = value_ / length_;
      std::uint32_t t = dv >> m.table_shift();
      if (t > m.table_size()) t = m.table_size();  // only a corrupt stream gets here
      sym = table[t];
      std::uint32_t n = table[t + 1] + 1;
      while (n > sym + 1) {  // bisection within the table's bracket
        const std::uint32_t k = (sym + n) >> 1;
        if (m.low(k) > dv) {
          n = k;
        } else {
          sym = k;
        }
      }
      x = m.low(sym) * length_;
      if (sym != m.last()) y = m.low(sym + 1) * length_;
    } else {
      x = sym = 0;
      length_ >>= kSymbolShift;
      std::uint32_t n = m.symbols(), k = n >> 1;
      do {
        const std::uint32_t z = length_ * m.low(k);
        if (z > value_) {
          n = k;
          y = z;
        } else {
          sym = k;
          x = z;
        }
      } while ((k = (sym + n) >> 1) != sym);
    }
    value_ -= x;
    length_ = y - x;
    if (length_ < kMinLength) renormalise();
    m.count(sym);
    return sym;
  }

  // `bits` (1..32) raw bits, coded with a uniform distribution.
  std::uint32_t read_bits(std::uint32_t bits) {
    if (bits > 19) {
      const std::uint32_t low = read_short();
      return (read_bits(bits - 16) << 16) | low;
    }
    const std::uint32_t sym = value_ / (length_ >>= bits);
    value_ -= length_ * sym;
    if (length_ < kMinLength) renormalise();
    return sym;
  }
  std::uint32_t read_short() { return read_bits(16); }
  std::uint32_t read_int() {
    const std::uint32_t low = read_short();
    return (read_short() << 16) | low;
  }
  std::uint64_t read_int64() {
    const std::uint64_t low = read_int();
    return (std::uint64_t(read_int()) << 32) | low;
  }

 private:
  std::uint8_t byte() {
    if (next_ == end_) throw StreamOverrun{};
    return *next_++;
  }
  void renormalise() {
    do {
      value_ = (value_ << 8) | byte();
    } while ((length_ <<= 8) < kMinLength);
  }

  const std::uint8_t* next_ = nullptr;
  const std::uint8_t* end_ = nullptr;
  std::uint32_t value_ = 0, length_ = kMaxLength;
};

}  // namespace ramus::laz
