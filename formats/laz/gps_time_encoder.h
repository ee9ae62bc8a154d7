// GPS time encoding shared by gpstime11 (version 2) and point14 (layered version 3): up to four
// interleaved time sequences; a time is coded as a multiple of its sequence's last difference
// plus a correction, as "unchanged" (version 2 only: version 3 says so in the returns layer),
// as a switch to another sequence it is close to, or in full (Isenburg 2013, section 4.2).
// The codes are those the decoders in item_decoders.cpp and layered_decoder.cpp read, and the
// state updates mirror theirs exactly.
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>

#include "formats/laz/adaptive_models.h"
#include "formats/laz/gps_sequences.h"
#include "formats/laz/integer_encoder.h"
#include "formats/laz/range_encoder.h"

namespace ramus::laz {

// `layered`: the version 3 code table (no "unchanged" codes; 5 zero-difference symbols and the
// full time at 511) instead of version 2's (6 symbols; unchanged 511, full time 512).
inline void encode_gps_time(RangeEncoder& e, SymbolModel& multi_model, SymbolModel& zero_model,
                            IntegerEncoder& ic, GpsSequences& s, std::uint64_t t, bool layered) {
  constexpr std::int32_t kMulti = 500, kMinus = -10;
  const std::uint32_t code_full = layered ? 511 : 512;
  auto fits = [](std::int64_t d) {
    return d >= std::numeric_limits<std::int32_t>::min() &&
           d <= std::numeric_limits<std::int32_t>::max();
  };
  auto times = [](std::int32_t a, std::int32_t b) {
    return std::int32_t(std::uint32_t(a) * std::uint32_t(b));
  };
  auto other_sequence = [&](std::uint32_t& i) {
    for (i = 1; i < 4; ++i) {
      if (fits(std::int64_t(t - s.time[(s.last + i) & 3]))) return true;
    }
    return false;
  };
  auto full = [&] {
    ic.encode(e, std::int32_t(s.time[s.last] >> 32), std::int32_t(t >> 32), 8);
    e.write_int(std::uint32_t(t));
    s.next = (s.next + 1) & 3;
    s.last = s.next;
    s.time[s.last] = t;
    s.diff[s.last] = 0;
    s.extreme[s.last] = 0;
  };
  auto extreme = [&](std::int32_t d) {
    if (++s.extreme[s.last] > 3) {
      s.diff[s.last] = d;
      s.extreme[s.last] = 0;
    }
  };
  for (;;) {
    const std::uint32_t l = s.last;
    const std::int64_t d64 = std::int64_t(t - s.time[l]);
    if (s.diff[l] == 0) {
      if (!layered && d64 == 0) {
        e.encode_symbol(zero_model, 0);
        return;
      }
      if (fits(d64)) {
        e.encode_symbol(zero_model, layered ? 0 : 1);
        ic.encode(e, 0, std::int32_t(d64), 0);
        s.diff[l] = std::int32_t(d64);
        s.time[l] = t;
        s.extreme[l] = 0;
        return;
      }
      std::uint32_t i;
      if (other_sequence(i)) {
        e.encode_symbol(zero_model, layered ? i + 1 : i + 2);
        s.last = (l + i) & 3;
        continue;
      }
      e.encode_symbol(zero_model, layered ? 1 : 2);
      full();
      return;
    }
    if (!layered && d64 == 0) {
      e.encode_symbol(multi_model, 511);  // unchanged
      return;
    }
    if (!fits(d64)) {
      std::uint32_t i;
      if (other_sequence(i)) {
        e.encode_symbol(multi_model, code_full + i);
        s.last = (l + i) & 3;
        continue;
      }
      e.encode_symbol(multi_model, code_full);
      full();
      return;
    }
    const std::int32_t d = std::int32_t(d64), last_diff = s.diff[l];
    const double ratio = double(d) / double(last_diff);
    const std::int64_t m = ratio >= kMulti   ? kMulti
                           : ratio <= kMinus ? kMinus
                                             : std::llround(ratio);
    if (m == 1) {
      e.encode_symbol(multi_model, 1);
      ic.encode(e, last_diff, d, 1);
      s.extreme[l] = 0;
    } else if (m > 1 && m < kMulti) {
      e.encode_symbol(multi_model, std::uint32_t(m));
      ic.encode(e, times(std::int32_t(m), last_diff), d, m < 10 ? 2 : 3);
    } else if (m == kMulti) {
      e.encode_symbol(multi_model, kMulti);
      ic.encode(e, times(kMulti, last_diff), d, 4);
      extreme(d);
    } else if (m < 0 && m > kMinus) {
      e.encode_symbol(multi_model, std::uint32_t(kMulti - m));
      ic.encode(e, times(std::int32_t(m), last_diff), d, 5);
    } else if (m == kMinus) {
      e.encode_symbol(multi_model, std::uint32_t(kMulti - kMinus));
      ic.encode(e, times(kMinus, last_diff), d, 6);
      extreme(d);
    } else {  // m == 0
      e.encode_symbol(multi_model, 0);
      ic.encode(e, 0, d, 7);
      extreme(d);
    }
    s.time[l] = t;
    return;
  }
}

}  // namespace ramus::laz
