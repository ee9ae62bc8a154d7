#include "formats/rmb/rmb_io.h"

#include <array>
#include <bit>
#include <cmath>
#include <cstring>

#include "core/number_text.h"

namespace ramus::rmb {

namespace {

std::string number(double v) { return shortest_text(v); }

// Printable text for a dump: quotes, with bytes outside 0x20..0x7e escaped.
std::string quoted(std::string_view s) {
  static const char* kHex = "0123456789abcdef";
  std::string out = "\"";
  for (unsigned char c : s) {
    if (c >= 0x20 && c < 0x7f && c != '"' && c != '\\') {
      out += char(c);
    } else {
      out += "\\x";
      out += kHex[c >> 4];
      out += kHex[c & 15];
    }
  }
  return out + "\"";
}

std::array<std::uint32_t, 256> make_crc_table() {
  std::array<std::uint32_t, 256> t{};
  for (std::uint32_t i = 0; i < 256; ++i) {
    std::uint32_t c = i;
    for (int k = 0; k < 8; ++k) c = (c & 1) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
    t[i] = c;
  }
  return t;
}

}  // namespace

RmbError::RmbError(std::size_t at, const std::string& expected)
    : std::runtime_error("byte " + std::to_string(at) + ": " + expected), offset(at) {}

std::uint32_t crc32(std::string_view bytes) {
  static const std::array<std::uint32_t, 256> table = make_crc_table();
  std::uint32_t c = 0xFFFFFFFFu;
  for (unsigned char b : bytes) c = table[(c ^ b) & 0xFF] ^ (c >> 8);
  return c ^ 0xFFFFFFFFu;
}

void Writer::u16(std::uint16_t v) {
  u8(std::uint8_t(v));
  u8(std::uint8_t(v >> 8));
}

void Writer::u32(std::uint32_t v) {
  for (int i = 0; i < 4; ++i) u8(std::uint8_t(v >> (8 * i)));
}

void Writer::varint(std::uint64_t v) {
  while (v >= 0x80) {
    u8(std::uint8_t(v | 0x80));
    v >>= 7;
  }
  u8(std::uint8_t(v));
}

void Writer::real(double v) {
  if (quantized_ && std::isfinite(v)) {
    const double k = std::nearbyint(std::ldexp(v, -exponent_));
    if (std::fabs(k) <= double(kMaxQuantumMultiple)) {
      varint(zigzag(std::int64_t(k)) << 1);
      return;
    }
  }
  if (quantized_) varint(1);  // the escape: an exact f64 follows
  f64(v);
}

void Writer::f64(double v) {
  const std::uint64_t bits = std::bit_cast<std::uint64_t>(v);
  for (int i = 0; i < 8; ++i) u8(std::uint8_t(bits >> (8 * i)));
}

void Writer::str(std::string_view s) {
  varint(s.size());
  out_.append(s);
}

void Reader::need(std::size_t n, const char* field) const {
  if (n > end_ - pos_) {
    fail(std::string("expected ") + field + " (" + std::to_string(n) + " byte(s)), found " +
         (pos_ >= data_.size() ? "the end of the file" : "the end of the section"));
  }
}

void Reader::note(std::size_t at, const char* field, std::string value) {
  trace_->push_back(TraceEntry{at, pos_ - at, field, std::move(value)});
}

void Reader::heading(const std::string& text) {
  if (trace_) trace_->push_back(TraceEntry{pos_, 0, text, ""});
}

std::uint8_t Reader::u8(const char* field) {
  need(1, field);
  const std::size_t at = pos_;
  const std::uint8_t v = std::uint8_t(data_[pos_++]);
  if (trace_) note(at, field, std::to_string(v));
  return v;
}

template <typename T>
T Reader::little_endian(const char* field) {
  need(sizeof(T), field);
  const std::size_t at = pos_;
  T v = 0;
  for (std::size_t i = 0; i < sizeof(T); ++i) v |= T(T(std::uint8_t(data_[pos_++])) << (8 * i));
  if (trace_) note(at, field, std::to_string(v));
  return v;
}

std::uint16_t Reader::u16(const char* field) { return little_endian<std::uint16_t>(field); }
std::uint32_t Reader::u32(const char* field) { return little_endian<std::uint32_t>(field); }

std::uint64_t Reader::varint(const char* field) {
  const std::size_t at = pos_;
  std::uint64_t v = 0;
  for (int shift = 0;; shift += 7) {
    need(1, field);
    const std::uint8_t b = std::uint8_t(data_[pos_++]);
    // The tenth byte may carry only the top bit of a 64-bit value; a longer or overlong
    // encoding would let two byte strings mean one value.
    if (shift == 63 && b > 1)
      fail_at(at, std::string("expected ") + field + ": varint overflows 64 bits");
    v |= std::uint64_t(b & 0x7F) << shift;
    if (!(b & 0x80)) {
      if (b == 0 && shift > 0) fail_at(at, std::string("expected ") + field + ": overlong varint");
      break;
    }
  }
  if (trace_) note(at, field, std::to_string(v));
  return v;
}

std::int64_t Reader::svarint(const char* field) {
  const std::size_t before = trace_ ? trace_->size() : 0;
  const std::int64_t v = unzigzag(varint(field));
  if (trace_ && trace_->size() > before) trace_->back().value = std::to_string(v);
  return v;
}

double Reader::f64(const char* field) {
  need(8, field);
  const std::size_t at = pos_;
  std::uint64_t bits = 0;
  for (int i = 0; i < 8; ++i) bits |= std::uint64_t(std::uint8_t(data_[pos_++])) << (8 * i);
  const double v = std::bit_cast<double>(bits);
  if (trace_) note(at, field, number(v));
  return v;
}

double Reader::real(const char* field) {
  if (!quantized_) return f64(field);
  const std::size_t at = pos_;
  std::vector<TraceEntry>* trace = trace_;
  trace_ = nullptr;  // one trace line for the whole number, below
  const std::uint64_t u = varint(field);
  double v = 0;
  if (u == 1) {
    v = f64(field);
  } else if (u & 1) {
    trace_ = trace;
    fail_at(at, "expected a quantized number (even) or the escape 1");
  } else {
    const std::int64_t k = unzigzag(u >> 1);
    if (k > kMaxQuantumMultiple || k < -kMaxQuantumMultiple) {
      trace_ = trace;
      fail_at(at, "expected a quantized multiple of at most 2^52");
    }
    v = std::ldexp(double(k), exponent_);
  }
  trace_ = trace;
  if (trace_) note(at, field, number(v) + (u == 1 ? " (exact)" : ""));
  return v;
}

std::string Reader::str(const char* field, std::size_t max_len) {
  const std::size_t at = pos_;
  const std::uint64_t n = varint(field);
  if (n > max_len)
    fail_at(at, std::string("expected ") + field + " of at most " + std::to_string(max_len) +
                    " bytes, found length " + std::to_string(n));
  need(std::size_t(n), field);
  std::string s(data_.substr(pos_, std::size_t(n)));
  pos_ += std::size_t(n);
  if (trace_) {
    trace_->back().size = pos_ - at;
    trace_->back().value = quoted(s);
  }
  return s;
}

std::string_view Reader::raw(const char* field, std::size_t n) {
  need(n, field);
  const std::size_t at = pos_;
  std::string_view s = data_.substr(pos_, n);
  pos_ += n;
  if (trace_) note(at, field, quoted(s));
  return s;
}

std::uint64_t Reader::bounded(const char* field, std::uint64_t max) {
  const std::size_t at = pos_;
  const std::uint64_t v = varint(field);
  if (v > max) {
    fail_at(at, std::string("expected ") + field + " <= " + std::to_string(max) + ", found " +
                    std::to_string(v));
  }
  return v;
}

std::size_t Reader::count(const char* field, std::uint64_t max, std::size_t min_bytes) {
  const std::size_t at = pos_;
  const std::uint64_t n = bounded(field, max);
  if (n > left() / min_bytes) {
    fail_at(at, std::string("expected ") + field + " that fits the " + std::to_string(left()) +
                    " byte(s) left, found " + std::to_string(n));
  }
  return std::size_t(n);
}

std::string hex_bytes(std::string_view bytes, std::size_t max) {
  static const char* kHex = "0123456789abcdef";
  std::string out;
  for (std::size_t i = 0; i < bytes.size() && i < max; ++i) {
    if (i) out += ' ';
    out += kHex[std::uint8_t(bytes[i]) >> 4];
    out += kHex[std::uint8_t(bytes[i]) & 15];
  }
  if (bytes.size() > max) out += " ..";
  return out;
}

}  // namespace ramus::rmb
