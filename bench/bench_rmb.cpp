// Decoding speed of .rmb files (docs/binary-format.md, Sizes): for each file, the best of
// several rounds of decode_rmb with full verification (checksum, bounds, expression proofs),
// in nanoseconds per byte. bench/bench_rmb.sh runs it beside the size table.
//   bench_rmb FILE.rmb...   ->   one line per file: "<file> <bytes> <ns per decode> <ns/byte>"
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

#include "formats/rmb/rmb.h"

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: bench_rmb FILE.rmb...\n");
    return 2;
  }
  for (int i = 1; i < argc; ++i) {
    std::ifstream in(argv[i], std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    const std::string bytes = ss.str();
    try {
      ramus::decode_rmb(bytes);
    } catch (const ramus::RmbError& e) {
      std::fprintf(stderr, "%s: %s\n", argv[i], e.what());
      return 1;
    }
    // Enough decodes per round for a measurable time; the best round is the least disturbed.
    const int reps =
        int(std::max<std::size_t>(20, 2'000'000 / std::max<std::size_t>(bytes.size(), 1)));
    double best = 1e300;
    std::size_t sink = 0;
    for (int round = 0; round < 5; ++round) {
      const auto t0 = std::chrono::steady_clock::now();
      for (int r = 0; r < reps; ++r) sink += ramus::decode_rmb(bytes).productions.size();
      const auto t1 = std::chrono::steady_clock::now();
      best = std::min(best, std::chrono::duration<double, std::nano>(t1 - t0).count() / reps);
    }
    std::printf("%s %zu %.0f %.1f\n", argv[i], bytes.size(), best, best / double(bytes.size()));
    if (sink == 0) std::fprintf(stderr, "(no productions decoded)\n");
  }
  return 0;
}
