// The optional zstd stage of the .rmb format (docs/binary-format.md, flag bit 1): everything
// after the 8-byte header and before the CRC-32 -- the section table and the sections -- as one
// zstd frame. The CLI links libzstd (formats/rmb/rmb_zstd.cpp); the embeddable runtime is built
// without it (runtime/rmb_zstd_absent.cpp) and rejects such files with a clear error.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace ramus {

// Whether this build can write and read zstd .rmb files.
bool rmb_zstd_available();

// One zstd frame of `data` (level 19, the content size in the frame header, no dictionary),
// deterministic for a given libzstd. Throws RmbError when zstd is not available.
std::string rmb_zstd_compress(std::string_view data);

// The content of the frame that starts at byte `offset` of the file, at most `max_size` bytes.
// Throws RmbError at `offset` for a damaged frame, a frame of unknown or too large content
// size, or when zstd is not available.
std::string rmb_zstd_decompress(std::string_view frame, std::size_t offset, std::size_t max_size);

}  // namespace ramus
