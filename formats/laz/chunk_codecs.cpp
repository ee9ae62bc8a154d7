#include "formats/laz/chunk_codecs.h"

#include <cstring>
#include <vector>

#include "formats/laz/item_decoders.h"
#include "formats/laz/layered_decoder.h"

namespace ramus::laz {
namespace {

class PointwiseChunks final : public ChunkCodec {
 public:
  PointwiseChunks(std::vector<std::unique_ptr<ItemDecoder>> items, std::vector<std::size_t> sizes)
      : items_(std::move(items)), sizes_(std::move(sizes)) {
    for (auto s : sizes_) record_ += s;
  }

  void start(const std::uint8_t* begin, const std::uint8_t* end, std::size_t) override {
    begin_ = begin;
    end_ = end;
    first_ = true;
  }

  void next(std::uint8_t* out) override {
    std::size_t at = 0;
    if (first_) {
      if (std::size_t(end_ - begin_) < record_) throw StreamOverrun{};
      std::memcpy(out, begin_, record_);
      for (std::size_t k = 0; k < items_.size(); at += sizes_[k++]) items_[k]->init(out + at);
      first_ = false;
      coded_ = false;
      return;
    }
    if (!coded_) {  // the coded stream follows the raw record (a one-point chunk needs none)
      dec_.start(begin_ + record_, end_);
      coded_ = true;
    }
    for (std::size_t k = 0; k < items_.size(); at += sizes_[k++]) items_[k]->decode(dec_, out + at);
  }

 private:
  std::vector<std::unique_ptr<ItemDecoder>> items_;
  std::vector<std::size_t> sizes_;
  std::size_t record_ = 0;
  const std::uint8_t* begin_ = nullptr;
  const std::uint8_t* end_ = nullptr;
  bool first_ = true, coded_ = false;
  RangeDecoder dec_;
};

}  // namespace

std::unique_ptr<ChunkCodec> make_chunk_codec(const LaszipVlr& vlr, std::string& why) {
  if (vlr.compressor == kCompressorLayered) return make_layered_decoder(vlr, why);
  std::vector<std::unique_ptr<ItemDecoder>> items;
  std::vector<std::size_t> sizes;
  for (const auto& item : vlr.items) {
    auto d = make_v2_decoder(item);
    if (!d) {
      why = "LAZ item " + item_name(item) + " (" + std::to_string(item.size) +
            " bytes) is not supported";
      return nullptr;
    }
    items.push_back(std::move(d));
    sizes.push_back(item.size);
  }
  return std::make_unique<PointwiseChunks>(std::move(items), std::move(sizes));
}

}  // namespace ramus::laz
