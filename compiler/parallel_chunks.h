// Running the chunks of a derivation pass (compiler/derive.cpp) on several threads.
//
// Two implementations of the one function, chosen at link time: parallel_chunks_tbb.cpp (TBB,
// in ramus_compiler) and runtime/parallel_chunks_threads.cpp (std::thread only, in the
// embeddable ramus_runtime, which links no TBB). The chunks are fixed by the pass, so the
// output never depends on which implementation or how many threads ran them.
#pragma once

#include <cstddef>
#include <functional>

namespace ramus {

// Calls run(c) once for every c in 0..nchunks-1 on up to `threads` threads (0: all hardware
// threads). `run` must not throw; it records its own errors.
void run_chunks_parallel(std::size_t nchunks, int threads,
                         const std::function<void(std::size_t)>& run);

}  // namespace ramus
