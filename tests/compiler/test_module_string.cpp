// ModuleString's layout: 16-bit parameter offsets with a full offset per block of 1024 modules
// must give every module's parameters back across block boundaries, whether the string was
// pushed module by module or filled in place as a derivation pass fills it.
#include <catch2/catch.hpp>
#include <vector>

#include "compiler/module_string.h"

using namespace ramus;

namespace {
// Module i has (i * 7) % 65 parameters (0..64), its k-th being i + k / 100.
std::uint32_t count_of(std::size_t i) { return std::uint32_t((i * 7) % 65); }
double value_of(std::size_t i, std::uint32_t k) { return double(i) + k / 100.0; }
}  // namespace

TEST_CASE("module string: offsets survive blocks of up to 64 parameters per module",
          "[module_string]") {
  const std::size_t n = 5000;  // about 160,000 parameters: offsets far beyond 16 bits
  ModuleString pushed;
  std::vector<double> p(64);
  for (std::size_t i = 0; i < n; ++i) {
    for (std::uint32_t k = 0; k < count_of(i); ++k) p[k] = value_of(i, k);
    pushed.push(ir::SymbolId(i % 300), p.data(), count_of(i));
  }
  REQUIRE(pushed.size() == n);
  REQUIRE(pushed.param_count() > 65536 * 2);
  for (std::size_t i = 0; i < n; ++i) {
    REQUIRE(pushed.symbol(i) == ir::SymbolId(i % 300));
    REQUIRE(pushed.nparams(i) == count_of(i));
    for (std::uint32_t k = 0; k < count_of(i); ++k) REQUIRE(pushed.param(i, k) == value_of(i, k));
  }
  REQUIRE(pushed.begin(n) == pushed.param_count());

  // The same string filled in place, in the order a derivation pass writes it.
  ModuleString filled;
  filled.resize_for_fill(n, pushed.param_count());
  std::uint32_t pofs = 0;
  for (std::size_t i = 0; i < n; ++i) {
    filled.symbols_data()[i] = ir::SymbolId(i % 300);
    filled.set_begin(i, pofs);
    for (std::uint32_t k = 0; k < count_of(i); ++k) filled.params_data()[pofs++] = value_of(i, k);
  }
  CHECK(filled == pushed);
  CHECK(filled.bytes() == pushed.bytes());
  CHECK(pushed.bytes() == n * 4 + 2 + (n / 1024 + 1) * 4 + pushed.param_count() * 8);
}

TEST_CASE("module string: a parametric module costs 12 bytes", "[module_string]") {
  CHECK(module_bytes(1) == 12);
  CHECK(module_bytes(0) == 4);
}

TEST_CASE("module string: more than 64 parameters are refused", "[module_string]") {
  ModuleString s;
  std::vector<double> p(65, 1.0);
  CHECK_NOTHROW(s.push(ir::SymbolId(20), p.data(), 64));
  CHECK_THROWS_AS(s.push(ir::SymbolId(20), p.data(), 65), std::length_error);
  CHECK(s.size() == 1);
}
