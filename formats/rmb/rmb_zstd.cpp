#include "formats/rmb/rmb_zstd.h"

#include <zstd.h>

#include "formats/rmb/rmb_io.h"

namespace ramus {

bool rmb_zstd_available() { return true; }

std::string rmb_zstd_compress(std::string_view data) {
  std::string out(ZSTD_compressBound(data.size()), '\0');
  const std::size_t n = ZSTD_compress(out.data(), out.size(), data.data(), data.size(), 19);
  if (ZSTD_isError(n)) {
    throw rmb::RmbError(0, std::string("cannot encode: zstd failed: ") + ZSTD_getErrorName(n));
  }
  out.resize(n);
  return out;
}

std::string rmb_zstd_decompress(std::string_view frame, std::size_t offset, std::size_t max_size) {
  // The frame must say how large its content is, so memory is bounded before anything is read.
  const unsigned long long size = ZSTD_getFrameContentSize(frame.data(), frame.size());
  if (size == ZSTD_CONTENTSIZE_ERROR || size == ZSTD_CONTENTSIZE_UNKNOWN) {
    throw rmb::RmbError(offset, "expected a zstd frame with its content size");
  }
  if (size > max_size) {
    throw rmb::RmbError(offset, "expected zstd content of at most " + std::to_string(max_size) +
                                    " bytes, found " + std::to_string(size));
  }
  if (ZSTD_findFrameCompressedSize(frame.data(), frame.size()) != frame.size()) {
    throw rmb::RmbError(offset, "expected exactly one zstd frame before the CRC-32");
  }
  std::string out(std::size_t(size), '\0');
  const std::size_t n = ZSTD_decompress(out.data(), out.size(), frame.data(), frame.size());
  if (ZSTD_isError(n) || n != size) {
    throw rmb::RmbError(offset, std::string("expected a valid zstd frame (") +
                                    (ZSTD_isError(n) ? ZSTD_getErrorName(n) : "short content") +
                                    ")");
  }
  return out;
}

}  // namespace ramus
