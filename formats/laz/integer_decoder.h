// Decoding side of LASzip's integer compressor (see integer_models.h): value = prediction +
// corrector, wrapped into the value range.
#pragma once

#include "formats/laz/integer_models.h"
#include "formats/laz/range_decoder.h"

namespace ramus::laz {

class IntegerDecoder : public IntegerModels {
 public:
  using IntegerModels::IntegerModels;

  std::int32_t decode(RangeDecoder& dec, std::int32_t prediction, std::uint32_t context = 0) {
    // Unsigned arithmetic: wrapping is the format's rule for 32-bit values and is defined.
    std::uint32_t real = std::uint32_t(prediction) + std::uint32_t(corrector(dec, context));
    if (corr_range_ != 0) {
      if (std::int32_t(real) < 0) {
        real += corr_range_;
      } else if (real >= corr_range_) {
        real -= corr_range_;
      }
    }
    return std::int32_t(real);
  }

 private:
  std::int32_t corrector(RangeDecoder& dec, std::uint32_t context) {
    k_ = dec.decode_symbol(k_models_[context]);
    if (k_ == 0) return std::int32_t(dec.decode_bit(zero_or_one_));
    if (k_ >= 32) return corr_min_;
    std::uint32_t c;
    if (k_ <= bits_high_) {
      c = dec.decode_symbol(low_models_[k_ - 1]);
    } else {
      const std::uint32_t k1 = k_ - bits_high_;
      c = dec.decode_symbol(low_models_[k_ - 1]);
      c = (c << k1) | dec.read_bits(k1);
    }
    // c in [0, 2^(k-1)) stands for [-(2^k - 1), -2^(k-1)], c in [2^(k-1), 2^k) for [2^(k-1)+1,
    // 2^k].
    if (c >= (1u << (k_ - 1))) return std::int32_t(c + 1);
    return std::int32_t(c - ((1u << k_) - 1));
  }
};

}  // namespace ramus::laz
