#include "formats/rmb/rmb_io.h"

#include <array>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <optional>

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

double decimal_value(std::int64_t m, int d) {
  char text[40];
  const int n = std::snprintf(text, sizeof text, "%llde-%d", static_cast<long long>(m), d);
  double v = 0;
  std::from_chars(text, text + n, v);
  return v;
}

namespace {

// The decimal code zigzag(m) << 3 | d of v = m * 10^-d, the fewest decimals d <= 6, when v has
// one (finite, not -0, |m| < 2^53, and m * 10^-d reads back as v bit for bit).
std::optional<std::uint64_t> decimal_code(double v) {
  if (!std::isfinite(v) || (v == 0 && std::signbit(v))) return std::nullopt;
  static const double kPow10[] = {1, 10, 100, 1e3, 1e4, 1e5, 1e6};
  for (int d = 0; d <= 6; ++d) {
    const double m = std::nearbyint(v * kPow10[d]);
    if (!(std::fabs(m) < 9007199254740992.0)) break;
    const auto mi = static_cast<std::int64_t>(m);
    if (d > 0 && mi % 10 == 0) continue;  // canonical: the fewest decimals
    if (std::bit_cast<std::uint64_t>(decimal_value(mi, d)) == std::bit_cast<std::uint64_t>(v)) {
      return (zigzag(mi) << 3) | std::uint64_t(d);
    }
  }
  return std::nullopt;
}

std::size_t varint_length(std::uint64_t v) {
  std::size_t n = 1;
  for (; v >= 0x80; v >>= 7) ++n;
  return n;
}

}  // namespace

// Version 2, quantized (docs/binary-format.md, `real`): the shortest of the exact value's
// decimal code, the quantized value's decimal code and its multiple k as
// ((zigzag(k) + 1) << 3) | 7, preferred in that order on equal length; nullopt: neither has a
// code (7 and the f64 of the quantized value follow). Quantizing the value it stores gives the
// same choice, so quantizing a quantized file changes nothing.
std::optional<double> Writer::quantum_multiple(double v) const {
  if (!std::isfinite(v)) return std::nullopt;
  // + 0.0: a value that rounds to -0 (-0 itself, or a negative one under half a quantum) is
  // stored as the multiple 0, which reads back as +0; so the value stored must be +0 too, or two
  // pool entries (+0 and -0) would be one after decoding and re-encoding.
  const double k = std::nearbyint(std::ldexp(v, -exponent_)) + 0.0;
  if (std::fabs(k) > double(kMaxQuantumMultiple)) return std::nullopt;
  return k;
}

Writer::QuantizedChoice Writer::choose_quantized(double v) const {
  double q = v;
  std::optional<std::uint64_t> tagged;
  if (const std::optional<double> k = quantum_multiple(v)) {
    q = std::ldexp(*k, exponent_);
    tagged = ((zigzag(std::int64_t(*k)) + 1) << 3) | 7;
  }
  QuantizedChoice best{std::nullopt, q};
  auto consider = [&](std::optional<std::uint64_t> code, double value) {
    if (code && (!best.code || varint_length(*code) < varint_length(*best.code))) {
      best = {code, value};
    }
  };
  consider(decimal_code(v), v);
  consider(decimal_code(q), q);
  consider(tagged, q);
  return best;
}

void Writer::real(double v) {
  if (!quantized_ && !decimal_) {  // version 1, exact
    f64(v);
    return;
  }
  if (!quantized_) {  // version 2, exact: a decimal, or 7 and the f64
    if (const std::optional<std::uint64_t> d = decimal_code(v)) {
      varint(*d);
    } else {
      varint(7);
      f64(v);
    }
    return;
  }
  if (!decimal_) {  // version 1, quantized: the multiple, or 1 and the f64
    if (const std::optional<double> k = quantum_multiple(v)) {
      varint(zigzag(std::int64_t(*k)) << 1);
    } else {
      varint(1);
      f64(v);
    }
    return;
  }
  const QuantizedChoice c = choose_quantized(v);
  if (c.code) {
    varint(*c.code);
  } else {
    varint(7);
    f64(c.value);
  }
}

double Writer::stored_real(double v) const {
  if (!quantized_ || !std::isfinite(v)) return v;
  if (decimal_) return choose_quantized(v).value;
  const std::optional<double> k = quantum_multiple(v);
  return k ? std::ldexp(*k, exponent_) : v;
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

double Reader::decimal_real(std::uint64_t u, std::size_t at) {
  const int d = int(u & 7);
  if (d == 7) {
    if (u != 7) fail_at(at, "expected a decimal number or the escape 7");
    return f64("f64");
  }
  const std::int64_t m = unzigzag(u >> 3);
  if (m >= (std::int64_t(1) << 53) || m <= -(std::int64_t(1) << 53) || (d > 0 && m % 10 == 0)) {
    fail_at(at, "expected a decimal number in its shortest form");
  }
  return decimal_value(m, d);
}

double Reader::real(const char* field) {
  if (!quantized_ && !decimal_) return f64(field);
  const std::size_t at = pos_;
  std::vector<TraceEntry>* trace = trace_;
  trace_ = nullptr;  // one trace line for the whole number, below
  struct Restore {   // the trace comes back on every exit, errors included
    std::vector<TraceEntry>*& slot;
    std::vector<TraceEntry>* value;
    ~Restore() { slot = value; }
  } restore{trace_, trace};
  const std::uint64_t u = varint(field);
  double v = 0;
  bool full = false;  // an f64 escape
  if (!quantized_ || (decimal_ && (u & 7) != 7) || (decimal_ && u == 7)) {
    full = u == 7;
    v = decimal_real(u, at);
  } else if (decimal_) {  // version 2, quantized: ((zigzag(k) + 1) << 3) | 7
    const std::int64_t k = unzigzag((u >> 3) - 1);
    if (k > kMaxQuantumMultiple || k < -kMaxQuantumMultiple) {
      fail_at(at, "expected a quantized multiple of at most 2^52");
    }
    v = std::ldexp(double(k), exponent_);
  } else if (u == 1) {
    full = true;
    v = f64(field);
  } else if (u & 1) {
    fail_at(at, "expected a quantized number (even) or the escape 1");
  } else {
    const std::int64_t k = unzigzag(u >> 1);
    if (k > kMaxQuantumMultiple || k < -kMaxQuantumMultiple) {
      fail_at(at, "expected a quantized multiple of at most 2^52");
    }
    v = std::ldexp(double(k), exponent_);
  }
  trace_ = trace;
  if (trace_) note(at, field, number(v) + (full ? " (f64)" : ""));
  return v;
}

std::string Reader::str(const char* field, std::size_t max_len) {
  std::string s(length_prefixed(field, max_len));
  if (trace_) trace_->back().value = quoted(s);
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

std::string_view Reader::blob(const char* field, std::size_t max_len) {
  const std::string_view s = length_prefixed(field, max_len);
  if (trace_) {
    char crc[16];
    std::snprintf(crc, sizeof crc, "%08x", crc32(s));
    trace_->back().value = std::to_string(s.size()) + " bytes, CRC-32 " + crc;
  }
  return s;
}

// A varint length of at most max_len, then that many bytes; the trace entry of the length
// grows to cover them.
std::string_view Reader::length_prefixed(const char* field, std::size_t max_len) {
  const std::size_t at = pos_;
  const std::uint64_t n = varint(field);
  if (n > max_len)
    fail_at(at, std::string("expected ") + field + " of at most " + std::to_string(max_len) +
                    " bytes, found length " + std::to_string(n));
  need(std::size_t(n), field);
  std::string_view s = data_.substr(pos_, std::size_t(n));
  pos_ += std::size_t(n);
  if (trace_) trace_->back().size = pos_ - at;
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
