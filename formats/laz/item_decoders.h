// Decoders of the items a compressed LAS point record is made of. Each chunk starts with the
// first point stored raw (`init`), the following points are decoded against the state the
// previous ones left (`decode`). Version 2 items (LASzip 2.x, point formats 0-3): point10,
// gpstime11, rgb12, extra bytes. The layered version 3 items of formats 6-8 are in
// layered_decoder.h and layered_items.h.
#pragma once

#include <cstdint>
#include <memory>

#include "formats/laz/laszip_vlr.h"
#include "formats/laz/range_decoder.h"

namespace ramus::laz {

class ItemDecoder {
 public:
  virtual ~ItemDecoder() = default;
  virtual void init(const std::uint8_t* raw) = 0;
  virtual void decode(RangeDecoder& dec, std::uint8_t* out) = 0;
};

// The decoder of a version 2 item; nullptr when `item` is not one this reader decodes.
std::unique_ptr<ItemDecoder> make_v2_decoder(const Item& item);

}  // namespace ramus::laz
