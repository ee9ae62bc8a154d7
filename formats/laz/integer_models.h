// The models of LASzip's integer compressor, shared by its decoder and encoder. An integer is
// coded as a correction of a prediction: first k, the number of bits of the corrector (one
// symbol model per context), then the corrector's position in its interval of 2^k values, by a
// symbol model for k (the top `bits_high` bits when k is larger, the rest raw). k of the last
// value is kept because the point coders use it as context for the next coordinate.
#pragma once

#include <cstdint>
#include <limits>
#include <vector>

#include "formats/laz/adaptive_models.h"

namespace ramus::laz {

class IntegerModels {
 public:
  // `bits` of the values (32: full int32 range), `contexts` prediction contexts, `range` an
  // explicit value range (0: from bits).
  IntegerModels(std::uint32_t bits = 16, std::uint32_t contexts = 1, std::uint32_t bits_high = 8,
                std::uint32_t range = 0);
  void reset();

  std::uint32_t k() const { return k_; }

 protected:
  std::uint32_t bits_high_;
  std::uint32_t corr_bits_ = 0;   // significant bits of a corrector
  std::uint32_t corr_range_ = 0;  // 0 means the whole 2^32
  std::int32_t corr_min_ = 0, corr_max_ = 0;
  std::uint32_t k_ = 0;
  std::vector<SymbolModel> k_models_;    // one per context
  BitModel zero_or_one_;                 // corrector of k = 0: 0 or 1
  std::vector<SymbolModel> low_models_;  // index k - 1 for k = 1..corr_bits
};

}  // namespace ramus::laz
