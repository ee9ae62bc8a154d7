// ModuleString: a derived L-system string as a structure of arrays -- one symbol id per module,
// the low 16 bits of its parameter offset, the full offset of every 1024th module and one pool of
// doubles -- so a module costs 2 + 2 bytes plus 8 per parameter (F(1) costs 12 bytes) plus 4
// bytes per 1024 modules, and no heap allocation of its own (docs/engine.md, "The string").
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "compiler/ir.h"

namespace ramus {

// Buffers of 64 KB and more come from here. A few freed buffers are kept for the next pass or
// derivation instead of going back to the system, which hands them out again as fresh pages,
// one page fault each (docs/engine.md, "The string"): below 2 MB up to 8 (16 MB), from 2 MB
// up to 32 and an eighth of physical memory, resident while requests keep taking them; one idle
// for a second is given back lazily (the kernel may take its pages when short of memory).
void* allocate_buffer(std::size_t bytes);
void free_buffer(void* p, std::size_t bytes) noexcept;
// Gives every kept buffer back to the system (a long-lived process done deriving may call it)
// and returns their bytes.
std::size_t release_kept_buffers() noexcept;
inline constexpr std::size_t kLargeBuffer = std::size_t(2) << 20;
inline constexpr std::size_t kMidBuffer = std::size_t(64) << 10;

// An allocator whose resize() leaves new elements uninitialized: a derivation pass sizes the
// output exactly and then writes every element (in parallel), so zero-filling first would only
// touch every page twice.
template <typename T>
struct NoInitAllocator : std::allocator<T> {
  template <typename U>
  struct rebind {
    using other = NoInitAllocator<U>;
  };
  NoInitAllocator() = default;
  template <typename U>
  NoInitAllocator(const NoInitAllocator<U>&) noexcept {}
  T* allocate(std::size_t n) {
    if (n * sizeof(T) >= kMidBuffer) return static_cast<T*>(allocate_buffer(n * sizeof(T)));
    return std::allocator<T>::allocate(n);
  }
  void deallocate(T* p, std::size_t n) noexcept {
    if (n * sizeof(T) >= kMidBuffer) {
      free_buffer(p, n * sizeof(T));
    } else {
      std::allocator<T>::deallocate(p, n);
    }
  }
  template <typename U>
  void construct(U* p) noexcept {
    ::new (static_cast<void*>(p)) U;
  }
  template <typename U, typename... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
};
template <typename T>
using PodVector = std::vector<T, NoInitAllocator<T>>;

// A module holds at most this many parameters (a production binds at most ir::kMaxSlots): so
// the parameters of the modules before one in its block of 1024 span less than 2^16 and the low
// 16 bits of its offset plus the block's full offset give the offset.
inline constexpr std::uint32_t kMaxModuleParams = ir::kMaxSlots;
inline constexpr unsigned kBlockShift = 10;  // modules per block: 1024

class ModuleString {
 public:
  ModuleString() : low_{0}, base_{0} {}

  std::size_t size() const { return sym_.size(); }
  bool empty() const { return sym_.empty(); }
  ir::SymbolId symbol(std::size_t i) const { return sym_[i]; }
  std::uint32_t nparams(std::size_t i) const { return std::uint16_t(low_[i + 1] - low_[i]); }
  // Offset of module i's first parameter in the pool (i == size(): the pool's size).
  std::uint32_t begin(std::size_t i) const {
    const std::uint32_t b = base_[i >> kBlockShift];
    return b + std::uint16_t(low_[i] - std::uint16_t(b));
  }
  const double* params(std::size_t i) const { return params_.data() + begin(i); }
  double param(std::size_t i, std::uint32_t k) const { return params_[begin(i) + k]; }
  std::size_t param_count() const { return params_.size(); }

  // Appends a module; more than kMaxModuleParams parameters throw std::length_error.
  void push(ir::SymbolId s, const double* p = nullptr, std::uint32_t n = 0) {
    if (n > kMaxModuleParams) throw std::length_error("a module with more than 64 parameters");
    sym_.push_back(s);
    params_.insert(params_.end(), p, p + n);
    const auto end = std::uint32_t(params_.size());
    low_.push_back(std::uint16_t(end));
    if ((sym_.size() & kBlockMask) == 0) base_.push_back(end);
  }
  void push(ir::SymbolId s, std::initializer_list<double> p) {
    push(s, p.begin(), std::uint32_t(p.size()));
  }
  void clear() {
    sym_.clear();
    params_.clear();
    low_.assign(1, 0);
    base_.assign(1, 0);
  }
  std::size_t capacity() const { return sym_.capacity(); }
  std::size_t params_capacity() const { return params_.capacity(); }
  void reserve(std::size_t modules, std::size_t params) {
    sym_.reserve(modules);
    low_.reserve(modules + 1);
    base_.reserve((modules >> kBlockShift) + 1);
    params_.reserve(params);
  }
  // Sizes the arrays for `modules` modules and `params` parameters, to be filled in place
  // through set_begin() and the raw accessors below (parallel rewriting writes disjoint ranges).
  void resize_for_fill(std::size_t modules, std::size_t params) {
    sym_.resize(modules);
    low_.resize(modules + 1);
    base_.resize((modules >> kBlockShift) + 1);
    params_.resize(params);
    set_begin(modules, std::uint32_t(params));
  }
  // Records that module o's parameters start at offset `begin` of the pool.
  void set_begin(std::size_t o, std::uint32_t begin) {
    low_[o] = std::uint16_t(begin);
    if ((o & kBlockMask) == 0) base_[o >> kBlockShift] = begin;
  }
  ir::SymbolId* symbols_data() { return sym_.data(); }
  std::uint16_t* lows_data() { return low_.data(); }
  std::uint32_t* bases_data() { return base_.data(); }
  double* params_data() { return params_.data(); }
  const ir::SymbolId* symbols_data() const { return sym_.data(); }
  const std::uint16_t* lows_data() const { return low_.data(); }
  const double* params_data() const { return params_.data(); }

  // Bytes held by the arrays (their sizes, not capacities).
  std::size_t bytes() const {
    return sym_.size() * sizeof(ir::SymbolId) + low_.size() * sizeof(std::uint16_t) +
           base_.size() * sizeof(std::uint32_t) + params_.size() * sizeof(double);
  }
  void shrink_to_fit() {
    sym_.shrink_to_fit();
    low_.shrink_to_fit();
    base_.shrink_to_fit();
    params_.shrink_to_fit();
  }
  bool operator==(const ModuleString& o) const {
    return sym_ == o.sym_ && low_ == o.low_ && base_ == o.base_ && params_ == o.params_;
  }

 private:
  static constexpr std::size_t kBlockMask = (std::size_t(1) << kBlockShift) - 1;
  PodVector<ir::SymbolId> sym_;
  PodVector<std::uint16_t> low_;   // size() + 1: low 16 bits of each module's parameter offset
  PodVector<std::uint32_t> base_;  // the full offset of modules 0, 1024, 2048, ... (and size())
  PodVector<double> params_;
};

// Bytes one module costs with `nparams` parameters (besides the 4 bytes per 1024 modules of
// the block offsets).
constexpr std::size_t module_bytes(std::size_t nparams) {
  return sizeof(ir::SymbolId) + sizeof(std::uint16_t) + nparams * sizeof(double);
}

// The string in ABOP notation, parameters in shortest round-trip form: `F(1)[+A(0.5)]`. A blank
// separates a declared multi-letter name from a neighbouring name (`Apex B`), nothing else.
std::string to_text(const ir::Grammar& g, const ModuleString& s);

}  // namespace ramus
