// The GPS time state of LASzip's time coders: up to four interleaved sequences (multiple
// returns, several scanners), each with its last time, last difference and a counter of
// unusual multiples. Shared by the decoders and the encoder so that both update it alike.
#pragma once

#include <cstdint>

namespace ramus::laz {

struct GpsSequences {
  std::uint32_t last = 0, next = 0;
  std::uint64_t time[4] = {};
  std::int32_t diff[4] = {};
  std::int32_t extreme[4] = {};
  void reset(std::uint64_t first) {
    last = next = 0;
    for (int i = 0; i < 4; ++i) {
      time[i] = 0;
      diff[i] = 0;
      extreme[i] = 0;
    }
    time[0] = first;
  }
};

}  // namespace ramus::laz
