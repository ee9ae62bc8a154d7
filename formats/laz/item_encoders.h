// Encoders of version 2 items (point10, gpstime11, rgb12, extra bytes), the inverse of
// item_decoders.h: `init` takes a chunk's first record (stored raw), `encode` codes the next
// ones against the state the previous ones left.
#pragma once

#include <cstdint>
#include <memory>

#include "formats/laz/laszip_vlr.h"
#include "formats/laz/range_encoder.h"

namespace ramus::laz {

class ItemEncoder {
 public:
  virtual ~ItemEncoder() = default;
  virtual void init(const std::uint8_t* raw) = 0;
  virtual void encode(RangeEncoder& enc, const std::uint8_t* item) = 0;
};

// nullptr when `item` is not a version 2 item this writer encodes.
std::unique_ptr<ItemEncoder> make_v2_encoder(const Item& item);

}  // namespace ramus::laz
