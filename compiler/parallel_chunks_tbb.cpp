#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "compiler/parallel_chunks.h"

namespace ramus {

void run_chunks_parallel(std::size_t nchunks, int threads,
                         const std::function<void(std::size_t)>& run) {
  tbb::task_arena arena(threads > 0 ? threads : tbb::task_arena::automatic);
  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, nchunks, 1),
                      [&](const tbb::blocked_range<std::size_t>& r) {
                        for (std::size_t c = r.begin(); c < r.end(); ++c) run(c);
                      });
  });
}

}  // namespace ramus
