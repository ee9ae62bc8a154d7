// The range encoder matching range_decoder.h: the same interval arithmetic, with carries
// propagated back into the bytes already written (the whole output is kept in memory, one
// chunk at a time).
#pragma once

#include <cstdint>
#include <vector>

#include "formats/laz/adaptive_models.h"

namespace ramus::laz {

class RangeEncoder {
 public:
  explicit RangeEncoder(std::vector<std::uint8_t>& out) : out_(out) {}

  void encode_bit(BitModel& m, std::uint32_t bit) {
    const std::uint32_t x = m.p0() * (length_ >> kBitShift);
    if (bit == 0) {
      length_ = x;
    } else {
      add(x);
      length_ -= x;
    }
    if (length_ < kMinLength) renormalise();
    m.count(bit != 0);
  }

  void encode_symbol(SymbolModel& m, std::uint32_t sym) {
    std::uint32_t x;
    if (sym == m.last()) {
      x = m.low(sym) * (length_ >> kSymbolShift);
      add(x);
      length_ -= x;
    } else {
      length_ >>= kSymbolShift;
      x = m.low(sym) * length_;
      add(x);
      length_ = m.low(sym + 1) * length_ - x;
    }
    if (length_ < kMinLength) renormalise();
    m.count(sym);
  }

  void write_bits(std::uint32_t bits, std::uint32_t sym) {
    if (bits > 19) {
      write_short(sym & 0xffff);
      sym >>= 16;
      bits -= 16;
    }
    add(sym * (length_ >>= bits));
    if (length_ < kMinLength) renormalise();
  }
  void write_short(std::uint32_t sym) { write_bits(16, sym); }
  void write_int(std::uint32_t v) {
    write_short(v & 0xffff);
    write_short(v >> 16);
  }

  // Flushes the interval: enough bytes that the decoder's four-byte look-ahead stays inside.
  void finish() {
    bool another_byte = true;
    if (length_ > 2 * kMinLength) {
      add(kMinLength);
      length_ = kMinLength >> 1;
    } else {
      add(kMinLength >> 1);
      length_ = kMinLength >> 9;
      another_byte = false;
    }
    renormalise();
    out_.push_back(0);
    out_.push_back(0);
    if (another_byte) out_.push_back(0);
  }

 private:
  void add(std::uint32_t x) {
    const std::uint32_t before = base_;
    base_ += x;
    if (before > base_) carry();
  }
  void carry() {
    std::size_t i = out_.size();
    while (i > start_ && out_[i - 1] == 0xff) out_[--i] = 0;
    if (i > start_) ++out_[i - 1];
  }
  void renormalise() {
    do {
      out_.push_back(std::uint8_t(base_ >> 24));
      base_ <<= 8;
    } while ((length_ <<= 8) < kMinLength);
  }

  std::vector<std::uint8_t>& out_;
  std::size_t start_ = out_.size();  // carries never reach bytes written before this stream
  std::uint32_t base_ = 0, length_ = kMaxLength;
};

}  // namespace ramus::laz
