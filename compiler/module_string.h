// ModuleString: a derived L-system string as a structure of arrays -- one symbol id per module,
// one parameter offset per module and one pool of doubles -- so a module costs 2 + 4 bytes plus
// 8 per parameter and no heap allocation of its own (F(1) costs 14 bytes).
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "compiler/ir.h"

namespace ramus {

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

class ModuleString {
 public:
  ModuleString() : begin_{0} {}

  std::size_t size() const { return sym_.size(); }
  bool empty() const { return sym_.empty(); }
  ir::SymbolId symbol(std::size_t i) const { return sym_[i]; }
  std::uint32_t nparams(std::size_t i) const { return begin_[i + 1] - begin_[i]; }
  const double* params(std::size_t i) const { return params_.data() + begin_[i]; }
  double param(std::size_t i, std::uint32_t k) const { return params_[begin_[i] + k]; }
  std::size_t param_count() const { return params_.size(); }

  void push(ir::SymbolId s, const double* p = nullptr, std::uint32_t n = 0) {
    sym_.push_back(s);
    params_.insert(params_.end(), p, p + n);
    begin_.push_back(std::uint32_t(params_.size()));
  }
  void push(ir::SymbolId s, std::initializer_list<double> p) {
    push(s, p.begin(), std::uint32_t(p.size()));
  }
  void clear() {
    sym_.clear();
    params_.clear();
    begin_.assign(1, 0);
  }
  void reserve(std::size_t modules, std::size_t params) {
    sym_.reserve(modules);
    begin_.reserve(modules + 1);
    params_.reserve(params);
  }
  // Sizes the arrays for `modules` modules and `params` parameters, to be filled in place
  // through the raw accessors below (parallel rewriting writes disjoint ranges).
  void resize_for_fill(std::size_t modules, std::size_t params) {
    sym_.resize(modules);
    begin_.resize(modules + 1);
    params_.resize(params);
    begin_[modules] = std::uint32_t(params);
  }
  ir::SymbolId* symbols_data() { return sym_.data(); }
  std::uint32_t* begins_data() { return begin_.data(); }
  double* params_data() { return params_.data(); }
  const ir::SymbolId* symbols_data() const { return sym_.data(); }

  // Bytes held by the three arrays (their sizes, not capacities).
  std::size_t bytes() const {
    return sym_.size() * sizeof(ir::SymbolId) + begin_.size() * sizeof(std::uint32_t) +
           params_.size() * sizeof(double);
  }
  void shrink_to_fit() {
    sym_.shrink_to_fit();
    begin_.shrink_to_fit();
    params_.shrink_to_fit();
  }
  bool operator==(const ModuleString& o) const {
    return sym_ == o.sym_ && begin_ == o.begin_ && params_ == o.params_;
  }

 private:
  PodVector<ir::SymbolId> sym_;
  PodVector<std::uint32_t> begin_;  // size() + 1 offsets into params_
  PodVector<double> params_;
};

// Bytes one module costs with `nparams` parameters.
constexpr std::size_t module_bytes(std::size_t nparams) {
  return sizeof(ir::SymbolId) + sizeof(std::uint32_t) + nparams * sizeof(double);
}

// The string in ABOP notation, parameters in shortest round-trip form: `F(1)[+A(0.5)]`. A blank
// separates a declared multi-letter name from a neighbouring name (`Apex B`), nothing else.
std::string to_text(const ir::Grammar& g, const ModuleString& s);

}  // namespace ramus
