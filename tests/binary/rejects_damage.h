// The shared damage check of the .rmb tests: every proper prefix of a file, and every copy with
// one byte changed, must be rejected with RmbError (the CRC-32 covers the whole file).
#pragma once

#include <catch2/catch.hpp>
#include <string>
#include <string_view>

#include "formats/rmb/rmb_codec.h"

namespace ramus::test {

template <typename Decode>
void check_rejects_truncation_and_damage(const std::string& bytes, Decode decode) {
  for (std::size_t n = 0; n < bytes.size(); ++n) {
    INFO(n);
    CHECK_THROWS_AS(decode(std::string_view(bytes).substr(0, n)), RmbError);
  }
  for (std::size_t i = 0; i < bytes.size(); ++i) {
    INFO(i);
    std::string bad = bytes;
    bad[i] = char(bad[i] ^ 0x41);
    CHECK_THROWS_AS(decode(std::string_view(bad)), RmbError);
  }
}

}  // namespace ramus::test
