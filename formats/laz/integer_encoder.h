// Encoding side of LASzip's integer compressor (see integer_models.h).
#pragma once

#include "formats/laz/integer_models.h"
#include "formats/laz/range_encoder.h"

namespace ramus::laz {

class IntegerEncoder : public IntegerModels {
 public:
  using IntegerModels::IntegerModels;

  void encode(RangeEncoder& enc, std::int32_t prediction, std::int32_t real,
              std::uint32_t context = 0) {
    std::int64_t corr = std::int64_t(real) - prediction;
    if (corr_range_ == 0) {
      corr = std::int32_t(std::uint32_t(corr));  // 32-bit values wrap
    } else if (corr < corr_min_) {
      corr += corr_range_;
    } else if (corr > corr_max_) {
      corr -= corr_range_;
    }
    write_corrector(enc, std::int32_t(corr), context);
  }

 private:
  void write_corrector(RangeEncoder& enc, std::int32_t c, std::uint32_t context) {
    // k: the smallest interval [-(2^k - 1), 2^k] that holds c.
    std::uint32_t c1 = c <= 0 ? 0u - std::uint32_t(c) : std::uint32_t(c) - 1;
    k_ = 0;
    while (c1 != 0) {
      c1 >>= 1;
      ++k_;
    }
    enc.encode_symbol(k_models_[context], k_);
    if (k_ == 0) {
      enc.encode_bit(zero_or_one_, std::uint32_t(c));
      return;
    }
    if (k_ >= 32) return;  // only corr_min, implied by k
    std::uint32_t v = c < 0 ? std::uint32_t(c) + ((1u << k_) - 1) : std::uint32_t(c) - 1;
    if (k_ <= bits_high_) {
      enc.encode_symbol(low_models_[k_ - 1], v);
    } else {
      const std::uint32_t k1 = k_ - bits_high_;
      enc.encode_symbol(low_models_[k_ - 1], v >> k1);
      enc.write_bits(k1, v & ((1u << k1) - 1));
    }
  }
};

}  // namespace ramus::laz
