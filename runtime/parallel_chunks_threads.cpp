// run_chunks_parallel for the embeddable runtime: plain std::thread workers taking chunks from
// an atomic counter, so the runtime needs no TBB. Same contract as the TBB version.
#include <algorithm>
#include <atomic>
#include <thread>
#include <vector>

#include "compiler/parallel_chunks.h"

namespace ramus {

void run_chunks_parallel(std::size_t nchunks, int threads,
                         const std::function<void(std::size_t)>& run) {
  std::size_t n = threads > 0 ? std::size_t(threads) : std::thread::hardware_concurrency();
  n = std::clamp<std::size_t>(n, 1, nchunks);
  std::atomic<std::size_t> next{0};
  auto work = [&] {
    for (std::size_t c; (c = next.fetch_add(1)) < nchunks;) run(c);
  };
  std::vector<std::thread> pool;
  try {
    for (std::size_t t = 1; t < n; ++t) pool.emplace_back(work);
  } catch (const std::system_error&) {
    // No more threads available: the calling thread and those started finish the chunks.
  }
  work();
  for (std::thread& t : pool) t.join();
}

}  // namespace ramus
