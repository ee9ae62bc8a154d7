// The layered version 3 items that follow point14 in point formats 7-10 and in records with
// extra bytes: rgb14 (one layer), rgbnir14 (two: colour, near infrared) and byte14 (one layer
// per extra byte). Each keeps one model set per scanner channel, switched with point14's.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "formats/laz/laszip_vlr.h"
#include "formats/laz/range_decoder.h"
#include "formats/laz/range_encoder.h"

namespace ramus::laz {

class LayerItemDecoder {
 public:
  virtual ~LayerItemDecoder() = default;
  virtual std::size_t layers() const = 0;
  // A chunk's first record of this item, raw, and its scanner channel.
  virtual void start(const std::uint8_t* raw, unsigned channel) = 0;
  // The next record; `streams`/`present` are this item's layers (an absent layer: the field
  // did not change in the chunk).
  virtual void decode(RangeDecoder* streams, const std::uint8_t* present, std::uint8_t* out,
                      unsigned channel) = 0;
};

class LayerItemEncoder {
 public:
  virtual ~LayerItemEncoder() = default;
  virtual std::size_t layers() const = 0;
  virtual void start(const std::uint8_t* raw, unsigned channel) = 0;
  virtual void encode(const std::uint8_t* item, unsigned channel) = 0;
  // Flushes the layers; a layer whose field never changed comes back empty.
  virtual void finish(std::vector<std::vector<std::uint8_t>>& layers) = 0;
};

// nullptr when `item` is not rgb14, rgbnir14 or byte14 version 3.
std::unique_ptr<LayerItemDecoder> make_layer_item_decoder(const Item& item);
std::unique_ptr<LayerItemEncoder> make_layer_item_encoder(const Item& item);

}  // namespace ramus::laz
