#include "formats/laz/adaptive_models.h"

namespace ramus::laz {

SymbolModel::SymbolModel(std::uint32_t symbols) : symbols_(symbols) {
  distribution_.resize(symbols);
  counts_.resize(symbols);
  if (symbols > 16) {
    std::uint32_t bits = 3;
    while (symbols > (1u << (bits + 2))) ++bits;
    table_size_ = 1u << bits;
    table_shift_ = kSymbolShift - bits;
    table_.resize(table_size_ + 2);
  }
  reset();
}

void SymbolModel::reset() {
  total_ = 0;
  cycle_ = symbols_;
  for (auto& c : counts_) c = 1;
  update();
  countdown_ = cycle_ = (symbols_ + 6) >> 1;
}

void SymbolModel::update() {
  if ((total_ += cycle_) > kSymbolMaxCount) {
    total_ = 0;
    for (auto& c : counts_) total_ += (c = (c + 1) >> 1);
  }
  const std::uint32_t scale = 0x80000000u / total_;
  std::uint32_t sum = 0;
  if (table_.empty()) {
    for (std::uint32_t k = 0; k < symbols_; ++k) {
      distribution_[k] = (scale * sum) >> (31 - kSymbolShift);
      sum += counts_[k];
    }
  } else {
    // table_[t] = the last symbol whose low end lies below t << table_shift_.
    std::uint32_t s = 0;
    for (std::uint32_t k = 0; k < symbols_; ++k) {
      distribution_[k] = (scale * sum) >> (31 - kSymbolShift);
      sum += counts_[k];
      const std::uint32_t w = distribution_[k] >> table_shift_;
      while (s < w) table_[++s] = k - 1;
    }
    table_[0] = 0;
    while (s <= table_size_) table_[++s] = symbols_ - 1;
  }
  cycle_ = (5 * cycle_) >> 2;
  const std::uint32_t max_cycle = (symbols_ + 6) << 3;
  if (cycle_ > max_cycle) cycle_ = max_cycle;
  countdown_ = cycle_;
}

}  // namespace ramus::laz
