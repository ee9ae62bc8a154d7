#include "formats/laz/integer_models.h"

namespace ramus::laz {

IntegerModels::IntegerModels(std::uint32_t bits, std::uint32_t contexts, std::uint32_t bits_high,
                             std::uint32_t range)
    : bits_high_(bits_high) {
  if (range != 0) {
    corr_range_ = range;
    while (range != 0) {
      range >>= 1;
      ++corr_bits_;
    }
    if (corr_range_ == (1u << (corr_bits_ - 1))) --corr_bits_;
    corr_min_ = -std::int32_t(corr_range_ / 2);
    corr_max_ = std::int32_t(std::int64_t(corr_min_) + corr_range_ - 1);
  } else if (bits != 0 && bits < 32) {
    corr_bits_ = bits;
    corr_range_ = 1u << bits;
    corr_min_ = -std::int32_t(corr_range_ / 2);
    corr_max_ = std::int32_t(std::int64_t(corr_min_) + corr_range_ - 1);
  } else {
    corr_bits_ = 32;
    corr_range_ = 0;
    corr_min_ = std::numeric_limits<std::int32_t>::min();
    corr_max_ = std::numeric_limits<std::int32_t>::max();
  }
  k_models_.assign(contexts, SymbolModel(corr_bits_ + 1));
  for (std::uint32_t i = 1; i <= corr_bits_; ++i) {
    low_models_.emplace_back(i <= bits_high_ ? 1u << i : 1u << bits_high_);
  }
}

void IntegerModels::reset() {
  k_ = 0;
  for (auto& m : k_models_) m.reset();
  zero_or_one_.reset();
  for (auto& m : low_models_) m.reset();
}

}  // namespace ramus::laz
