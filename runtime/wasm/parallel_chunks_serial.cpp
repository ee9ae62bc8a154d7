// run_chunks_parallel for the WebAssembly runtime (runtime/wasm/): the module is built without
// threads (no SharedArrayBuffer, so no cross-origin isolation needed on the page), so the
// chunks run one after another on the calling thread. The chunks are fixed by the pass, so the
// string equals the threaded one (compiler/parallel_chunks.h).
#include "compiler/parallel_chunks.h"

namespace ramus {

void run_chunks_parallel(std::size_t nchunks, int /*threads*/,
                         const std::function<void(std::size_t)>& run) {
  for (std::size_t c = 0; c < nchunks; ++c) run(c);
}

}  // namespace ramus
