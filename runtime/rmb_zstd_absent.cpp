// The embeddable runtime is built without libzstd (docs/runtime.md, size budget): .rmb files
// with the zstd flag are rejected with a clear error; `ramus build --zstd` files can be turned
// into plain ones with `ramus build` again without the flag.
#include "formats/rmb/rmb_io.h"
#include "formats/rmb/rmb_zstd.h"

namespace ramus {

bool rmb_zstd_available() { return false; }

std::string rmb_zstd_compress(std::string_view) {
  throw rmb::RmbError(0, "cannot encode: this runtime is built without zstd");
}

std::string rmb_zstd_decompress(std::string_view, std::size_t offset, std::size_t) {
  throw rmb::RmbError(offset,
                      "expected an uncompressed file: this runtime is built without zstd "
                      "(flag bit 1); rebuild the .rmb without --zstd");
}

}  // namespace ramus
