// ModuleString's layout: 16-bit parameter offsets with a full offset per block of 1024 modules
// must give every module's parameters back across block boundaries, whether the string was
// pushed module by module or filled in place as a derivation pass fills it.
#include <algorithm>
#include <catch2/catch.hpp>
#include <chrono>
#include <cstdint>
#include <thread>
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

// Freed buffers of 2 MB and more are kept for the next derivation (module_string.h): the next
// request that fits one (and needs at least half of it) gets it back instead of fresh pages,
// with its contents writable; a much smaller request does not take it.
TEST_CASE("module string: a freed large buffer serves the next derivation", "[module_string]") {
  release_kept_buffers();  // whatever earlier tests left
  const std::size_t big = std::size_t(24) << 20;
  auto* p = static_cast<unsigned char*>(allocate_buffer(big));
  p[0] = 1;
  p[big - 1] = 2;
  free_buffer(p, big);
  void* small = allocate_buffer(big / 3);  // less than half: not the kept buffer
  CHECK(small != p);
  auto* q = static_cast<unsigned char*>(allocate_buffer(big - 4096));
  CHECK(q == p);
  q[0] = 3;  // the kept pages are the buffer's own: writing them again works
  q[big - 4097] = 4;
  CHECK(q[0] == 3);
  CHECK(q[big - 4097] == 4);
  free_buffer(q, big - 4096);
  free_buffer(small, big / 3);

  // A kept buffer idle for a second is given back lazily (MADV_FREE) at the next large free or
  // request; it is still kept: the next request that fits takes it and may write every byte.
  std::this_thread::sleep_for(std::chrono::milliseconds(1100));
  void* other = allocate_buffer(big / 3);  // checks the idle buffers first
  auto* r = static_cast<unsigned char*>(allocate_buffer(big - 4096));
  CHECK(r == p);
  std::fill(r, r + big - 4096, std::uint8_t(5));
  CHECK(r[0] == 5);
  CHECK(r[big - 4097] == 5);
  free_buffer(r, big - 4096);
  free_buffer(other, big / 3);

  // A string filled after its arrays were kept by an earlier one reads back what was written.
  ModuleString a;
  a.resize_for_fill(1u << 20, 1u << 20);
  a = ModuleString();
  ModuleString b;
  b.resize_for_fill(1u << 20, 1u << 20);
  for (std::size_t i = 0; i < b.size(); ++i) {
    b.symbols_data()[i] = ir::SymbolId(i % 7);
    b.set_begin(i, std::uint32_t(i));
    b.params_data()[i] = double(i);
  }
  CHECK(b.symbol(12345) == 12345 % 7);
  CHECK(b.param(1048575, 0) == 1048575.0);
}
