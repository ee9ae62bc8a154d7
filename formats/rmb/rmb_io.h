// Byte-level primitives of the binary grammar format .rmb (docs/binary-format.md): LEB128
// varints, zigzag for signed values, raw little-endian IEEE 754 doubles, CRC-32, and a bounded
// reader that knows the byte offset of everything it reads. The reader can record a trace
// (offset, bytes, field, value) from which `ramus dump` prints its annotated listing.
//
// The codec that maps ir::Grammar to these bytes lives in formats/rmb/rmb_codec.h: this folder may
// use only core/, so it knows bytes, not grammars.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace ramus::rmb {

// A file that is not a valid .rmb: `offset` is where reading stopped, `what()` says what was
// expected there ("byte 37: expected a symbol id < 20, found 311").
struct RmbError : std::runtime_error {
  RmbError(std::size_t offset, const std::string& expected);
  std::size_t offset;
};

// CRC-32 (IEEE 802.3, reflected polynomial 0xEDB88320), as zlib's crc32().
std::uint32_t crc32(std::string_view bytes);

inline std::uint64_t zigzag(std::int64_t v) {
  return (std::uint64_t(v) << 1) ^ std::uint64_t(v >> 63);
}
inline std::int64_t unzigzag(std::uint64_t u) {
  return std::int64_t(u >> 1) ^ -std::int64_t(u & 1);
}

class Writer {
 public:
  void u8(std::uint8_t v) { out_.push_back(char(v)); }
  void u16(std::uint16_t v);  // little-endian
  void u32(std::uint32_t v);  // little-endian
  void varint(std::uint64_t v);
  void svarint(std::int64_t v) { varint(zigzag(v)); }
  void f64(double v);            // the 8 bytes of the IEEE 754 value, little-endian
  void str(std::string_view s);  // varint length, then the bytes
  void bytes(std::string_view s) { out_.append(s); }
  std::size_t size() const { return out_.size(); }
  std::string& data() { return out_; }

  // A real number (docs/binary-format.md, `real`): an f64, or once quantize(e) was called, the
  // nearest multiple k * 2^e as varint(zigzag(k) << 1), with varint 1 then f64 as the escape
  // for values too large or not finite. The error is at most 2^(e-1).
  void quantize(int exponent) {
    quantized_ = true;
    exponent_ = exponent;
  }
  // Reals of format version 2: a value whose shortest decimal text is m * 10^-d with d <= 6
  // and |m| < 2^53 is varint(zigzag(m) << 3 | d); any other is varint 7 and the f64. With
  // quantize(e) too, each real is the shortest of the exact value's decimal code, the quantized
  // value's, and the multiple k as ((zigzag(k) + 1) << 3) | 7 (choose_quantized).
  void decimal() { decimal_ = true; }
  void real(double v);
  // The value real(v) stores, as a reader gets it back (v itself unless quantized).
  double stored_real(double v) const;

 private:
  struct QuantizedChoice {
    std::optional<std::uint64_t> code;
    double value;
  };
  QuantizedChoice choose_quantized(double v) const;
  // The multiple of the quantum that stores v (+0 for what rounds to -0); nullopt when v is not
  // finite or too far from 0 for the multiple's range.
  std::optional<double> quantum_multiple(double v) const;

  std::string out_;
  bool quantized_ = false, decimal_ = false;
  int exponent_ = 0;
};

// One line of a dump: bytes [offset, offset + size) hold `field` = `value`; size 0 marks a
// heading (a section or a record) rather than a field.
struct TraceEntry {
  std::size_t offset = 0, size = 0;
  std::string field, value;
};

// Reads bytes [begin, end) of `data`; every read checks the bounds and throws RmbError with
// the absolute offset. Offsets reported are relative to the start of `data`.
class Reader {
 public:
  Reader(std::string_view data, std::size_t begin, std::size_t end,
         std::vector<TraceEntry>* trace = nullptr)
      : data_(data), pos_(begin), end_(end), trace_(trace) {}

  std::uint8_t u8(const char* field);
  std::uint16_t u16(const char* field);
  std::uint32_t u32(const char* field);
  std::uint64_t varint(const char* field);
  std::int64_t svarint(const char* field);
  double f64(const char* field);
  std::string str(const char* field, std::size_t max_len);
  std::string_view raw(const char* field, std::size_t n);  // n bytes, traced as text
  // A byte string as Writer::str writes it (varint length, then the bytes) whose contents are
  // data, not text (an embedded file): traced as its length and CRC-32, not quoted.
  std::string_view blob(const char* field, std::size_t max_len);
  // A real number as Writer::real writes it (f64 unless quantize(e) was called).
  void quantize(int exponent) {
    quantized_ = true;
    exponent_ = exponent;
  }
  void decimal() { decimal_ = true; }  // as Writer::decimal
  double real(const char* field);

  // A varint that must be <= max (counts, ids, indices): "expected <what> <= max".
  std::uint64_t bounded(const char* field, std::uint64_t max);
  // A count of records that each take at least `min_bytes`: cannot exceed what is left, which
  // keeps a corrupted count from allocating memory the file cannot back.
  std::size_t count(const char* field, std::uint64_t max, std::size_t min_bytes = 1);

  [[noreturn]] void fail(const std::string& expected) const { throw RmbError(pos_, expected); }
  [[noreturn]] void fail_at(std::size_t offset, const std::string& expected) const {
    throw RmbError(offset, expected);
  }
  void heading(const std::string& text);  // a trace line of size 0
  // Adds what the value just read stands for to its trace line: `kind  0 (tube)`.
  void explain(const std::string& meaning) {
    if (trace_ && !trace_->empty()) trace_->back().value += " (" + meaning + ")";
  }
  bool tracing() const { return trace_ != nullptr; }
  std::size_t pos() const { return pos_; }
  std::size_t left() const { return end_ - pos_; }
  bool at_end() const { return pos_ == end_; }

 private:
  void need(std::size_t n, const char* field) const;
  std::string_view length_prefixed(const char* field, std::size_t max_len);
  double decimal_real(std::uint64_t code, std::size_t at);  // a decimal code, at offset `at`
  void note(std::size_t at, const char* field, std::string value);
  template <typename T>
  T little_endian(const char* field);  // u16/u32: fixed-width little-endian

  std::string_view data_;
  std::size_t pos_, end_;
  std::vector<TraceEntry>* trace_;
  bool quantized_ = false, decimal_ = false;
  int exponent_ = 0;
};

// The decimal form of Writer::decimal: m * 10^-d as the nearest double (correctly rounded).
double decimal_value(std::int64_t m, int d);

// Quantum exponents a file may declare: 2^-60 .. 2^20.
inline constexpr int kMinQuantumExponent = -60, kMaxQuantumExponent = 20;
// The largest |k| of a quantized real (so that zigzag(k) << 1 fits 64 bits and k is exact).
inline constexpr std::int64_t kMaxQuantumMultiple = std::int64_t(1) << 52;

// "52 4d 42 1a" for a dump; at most `max` bytes, then "..".
std::string hex_bytes(std::string_view bytes, std::size_t max);

}  // namespace ramus::rmb
