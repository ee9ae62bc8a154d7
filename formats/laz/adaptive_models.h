// The adaptive probability models of the LASzip range coder, shared by the decoder and the
// encoder: a bit model and a multi-symbol model whose counts are rescaled periodically.
// The update schedule, the rescaling and the fixed-point widths (13-bit bit probabilities,
// 15-bit symbol distributions) are part of the LAZ format: encoder and decoder must adapt in
// lockstep, so they are exactly those of the LASzip compressor (Isenburg 2013, "LASzip: lossless
// compression of LiDAR data", section 3), which builds on Said's FastAC range coder.
#pragma once

#include <cstdint>
#include <vector>

namespace ramus::laz {

inline constexpr std::uint32_t kMinLength = 0x01000000u;  // renormalise below 2^24
inline constexpr std::uint32_t kMaxLength = 0xFFFFFFFFu;
inline constexpr int kBitShift = 13;  // bit probabilities are 13-bit fractions
inline constexpr std::uint32_t kBitMaxCount = 1u << kBitShift;
inline constexpr int kSymbolShift = 15;  // symbol distributions are 15-bit fractions
inline constexpr std::uint32_t kSymbolMaxCount = 1u << kSymbolShift;

// Probability of a 0 bit, re-estimated after a growing number of coded bits (4, 5, 6, ... 64).
class BitModel {
 public:
  BitModel() { reset(); }
  void reset() {
    zeros_ = 1;
    total_ = 2;
    p0_ = 1u << (kBitShift - 1);
    cycle_ = countdown_ = 4;
  }
  std::uint32_t p0() const { return p0_; }
  // Records one coded bit; re-estimates p0 when the countdown ends.
  void count(bool bit) {
    if (!bit) ++zeros_;
    if (--countdown_ == 0) update();
  }

 private:
  void update() {
    if ((total_ += cycle_) > kBitMaxCount) {
      total_ = (total_ + 1) >> 1;
      zeros_ = (zeros_ + 1) >> 1;
      if (zeros_ == total_) ++total_;
    }
    const std::uint32_t scale = 0x80000000u / total_;
    p0_ = (zeros_ * scale) >> (31 - kBitShift);
    cycle_ = (5 * cycle_) >> 2;
    if (cycle_ > 64) cycle_ = 64;
    countdown_ = cycle_;
  }
  std::uint32_t zeros_, total_, p0_, cycle_, countdown_;
};

// Cumulative distribution of `symbols` symbols (2..2048), rebuilt from the counts every
// `cycle` coded symbols. For more than 16 symbols a lookup table indexed by the top bits of the
// scaled value narrows the decoder's search (it changes no result, only speed).
class SymbolModel {
 public:
  explicit SymbolModel(std::uint32_t symbols);
  void reset();
  std::uint32_t symbols() const { return symbols_; }
  std::uint32_t last() const { return symbols_ - 1; }
  std::uint32_t low(std::uint32_t s) const { return distribution_[s]; }
  // Records one coded symbol; rebuilds the distribution when the countdown ends.
  void count(std::uint32_t s) {
    ++counts_[s];
    if (--countdown_ == 0) update();
  }
  const std::uint32_t* table() const { return table_.empty() ? nullptr : table_.data(); }
  std::uint32_t table_size() const { return table_size_; }
  std::uint32_t table_shift() const { return table_shift_; }

 private:
  void update();
  std::uint32_t symbols_;
  std::vector<std::uint32_t> distribution_, counts_, table_;
  std::uint32_t total_ = 0, cycle_ = 0, countdown_ = 0;
  std::uint32_t table_size_ = 0, table_shift_ = 0;
};

}  // namespace ramus::laz
