#include "formats/laz/layered_items.h"

#include <array>
#include <cstring>

#include "formats/laz/rgb_coding.h"
#include "formats/laz/v2_tables.h"

namespace ramus::laz {
namespace {

// Which channel's models and which channel's last record the next point uses. LASzip's
// version 3 items switch the models to the point's scanner channel, but keep reading and
// updating the previous channel's last record when the new channel was already seen in the
// chunk (a quirk its decoder and encoder share, so files depend on it; version 4 items fixed
// it). A channel not seen yet starts from the previous channel's last record.
class ChannelSwitch {
 public:
  void reset(unsigned channel) {
    for (auto& u : unused_) u = true;
    current_ = channel;
    unused_[channel] = false;
  }
  unsigned current() const { return current_; }
  // Returns the channel whose last record to use; calls start(new, from) for a first visit.
  template <typename Start>
  unsigned next(unsigned channel, Start&& start) {
    unsigned last = current_;
    if (channel != current_) {
      current_ = channel;
      if (unused_[channel]) {
        start(channel, last);
        unused_[channel] = false;
        last = channel;
      }
    }
    return last;
  }

 private:
  unsigned current_ = 0;
  bool unused_[4] = {true, true, true, true};
};

// rgb14 (6 bytes) and rgbnir14 (8 bytes).
struct RgbContext {
  RgbModels rgb;
  SymbolModel nir_used{4};
  SymbolModel nir_diff[2] = {SymbolModel(256), SymbolModel(256)};
  std::uint16_t last[4] = {};
  void start(const std::uint16_t* from) {
    rgb.reset();
    nir_used.reset();
    nir_diff[0].reset();
    nir_diff[1].reset();
    std::memcpy(last, from, sizeof last);
  }
};

void load_rgb(const std::uint8_t* raw, bool nir, std::uint16_t v[4]) {
  for (int i = 0; i < (nir ? 4 : 3); ++i) v[i] = get_le<std::uint16_t>(raw + 2 * i);
}

class RgbLayerDecoder final : public LayerItemDecoder {
 public:
  explicit RgbLayerDecoder(bool nir) : nir_(nir) {}
  std::size_t layers() const override { return nir_ ? 2 : 1; }
  void start(const std::uint8_t* raw, unsigned channel) override {
    std::uint16_t v[4] = {};
    load_rgb(raw, nir_, v);
    switch_.reset(channel);
    ctx_[channel].start(v);
  }
  void decode(RangeDecoder* streams, const std::uint8_t* present, std::uint8_t* out,
              unsigned channel) override {
    const unsigned l =
        switch_.next(channel, [&](unsigned c, unsigned from) { ctx_[c].start(ctx_[from].last); });
    RgbContext& m = ctx_[switch_.current()];
    std::uint16_t* last = ctx_[l].last;
    if (present[0]) decode_rgb(streams[0], m.rgb, last, last);
    if (nir_ && present[1]) {
      const std::uint32_t sym = streams[1].decode_symbol(m.nir_used);
      std::int32_t lo = last[3] & 0xff, hi = last[3] >> 8;
      if (sym & 1) lo = fold_u8(std::int32_t(streams[1].decode_symbol(m.nir_diff[0])) + lo);
      if (sym & 2) hi = fold_u8(std::int32_t(streams[1].decode_symbol(m.nir_diff[1])) + hi);
      last[3] = std::uint16_t(lo | (hi << 8));
    }
    for (int i = 0; i < (nir_ ? 4 : 3); ++i) put_le<std::uint16_t>(out + 2 * i, last[i]);
  }

 private:
  bool nir_;
  RgbContext ctx_[4];
  ChannelSwitch switch_;
};

class RgbLayerEncoder final : public LayerItemEncoder {
 public:
  explicit RgbLayerEncoder(bool nir) : nir_(nir) {}
  std::size_t layers() const override { return nir_ ? 2 : 1; }
  void start(const std::uint8_t* raw, unsigned channel) override {
    std::uint16_t v[4] = {};
    load_rgb(raw, nir_, v);
    switch_.reset(channel);
    ctx_[channel].start(v);
  }
  void encode(const std::uint8_t* item, unsigned channel) override {
    const unsigned l =
        switch_.next(channel, [&](unsigned c, unsigned from) { ctx_[c].start(ctx_[from].last); });
    RgbContext& m = ctx_[switch_.current()];
    std::uint16_t* last = ctx_[l].last;
    std::uint16_t v[4] = {};
    load_rgb(item, nir_, v);
    changed_[0] |= v[0] != last[0] || v[1] != last[1] || v[2] != last[2];
    encode_rgb(enc_[0], m.rgb, last, v);
    if (nir_) {
      changed_[1] |= v[3] != last[3];
      const std::uint32_t sym = std::uint32_t((v[3] & 0xff) != (last[3] & 0xff)) |
                                (std::uint32_t((v[3] >> 8) != (last[3] >> 8)) << 1);
      enc_[1].encode_symbol(m.nir_used, sym);
      if (sym & 1) enc_[1].encode_symbol(m.nir_diff[0], fold_u8((v[3] & 0xff) - (last[3] & 0xff)));
      if (sym & 2) enc_[1].encode_symbol(m.nir_diff[1], fold_u8((v[3] >> 8) - (last[3] >> 8)));
    }
    std::memcpy(last, v, sizeof v);
  }
  void finish(std::vector<std::vector<std::uint8_t>>& layers) override {
    for (std::size_t i = 0; i < this->layers(); ++i) {
      enc_[i].finish();
      layers.push_back(changed_[i] ? bytes_[i] : std::vector<std::uint8_t>{});
    }
  }

 private:
  bool nir_;
  RgbContext ctx_[4];
  ChannelSwitch switch_;
  std::array<std::vector<std::uint8_t>, 2> bytes_;
  RangeEncoder enc_[2] = {RangeEncoder(bytes_[0]), RangeEncoder(bytes_[1])};
  bool changed_[2] = {};
};

// byte14: every extra byte its own layer, coded as the difference to the last record's byte.
struct BytesContext {
  std::vector<SymbolModel> models;
  std::vector<std::uint8_t> last;
  BytesContext(std::size_t n = 0) : models(n, SymbolModel(256)), last(n) {}
  void start(const std::uint8_t* from) {
    for (auto& m : models) m.reset();
    std::memcpy(last.data(), from, last.size());
  }
};

class BytesLayerDecoder final : public LayerItemDecoder {
 public:
  explicit BytesLayerDecoder(std::size_t n) : n_(n) {
    for (auto& c : ctx_) c = BytesContext(n);
  }
  std::size_t layers() const override { return n_; }
  void start(const std::uint8_t* raw, unsigned channel) override {
    switch_.reset(channel);
    ctx_[channel].start(raw);
  }
  void decode(RangeDecoder* streams, const std::uint8_t* present, std::uint8_t* out,
              unsigned channel) override {
    const unsigned l = switch_.next(
        channel, [&](unsigned c, unsigned from) { ctx_[c].start(ctx_[from].last.data()); });
    BytesContext& m = ctx_[switch_.current()];
    std::uint8_t* last = ctx_[l].last.data();
    for (std::size_t i = 0; i < n_; ++i) {
      if (present[i]) {
        last[i] = fold_u8(std::int32_t(last[i] + streams[i].decode_symbol(m.models[i])));
      }
      out[i] = last[i];
    }
  }

 private:
  std::size_t n_;
  BytesContext ctx_[4];
  ChannelSwitch switch_;
};

class BytesLayerEncoder final : public LayerItemEncoder {
 public:
  explicit BytesLayerEncoder(std::size_t n) : n_(n), bytes_(n), changed_(n, false) {
    for (auto& c : ctx_) c = BytesContext(n);
    for (auto& b : bytes_) enc_.push_back(std::make_unique<RangeEncoder>(b));
  }
  std::size_t layers() const override { return n_; }
  void start(const std::uint8_t* raw, unsigned channel) override {
    switch_.reset(channel);
    ctx_[channel].start(raw);
  }
  void encode(const std::uint8_t* item, unsigned channel) override {
    const unsigned l = switch_.next(
        channel, [&](unsigned c, unsigned from) { ctx_[c].start(ctx_[from].last.data()); });
    BytesContext& m = ctx_[switch_.current()];
    std::uint8_t* last = ctx_[l].last.data();
    for (std::size_t i = 0; i < n_; ++i) {
      if (item[i] != last[i]) changed_[i] = true;
      enc_[i]->encode_symbol(m.models[i], fold_u8(std::int32_t(item[i]) - std::int32_t(last[i])));
      last[i] = item[i];
    }
  }
  void finish(std::vector<std::vector<std::uint8_t>>& layers) override {
    for (std::size_t i = 0; i < n_; ++i) {
      enc_[i]->finish();
      layers.push_back(changed_[i] ? bytes_[i] : std::vector<std::uint8_t>{});
    }
  }

 private:
  std::size_t n_;
  BytesContext ctx_[4];
  ChannelSwitch switch_;
  std::vector<std::vector<std::uint8_t>> bytes_;
  std::vector<std::unique_ptr<RangeEncoder>> enc_;
  std::vector<bool> changed_;
};

}  // namespace

std::unique_ptr<LayerItemDecoder> make_layer_item_decoder(const Item& item) {
  if (item.version != 3) return nullptr;
  if (item.type == ItemType::kRgb14 && item.size == 6)
    return std::make_unique<RgbLayerDecoder>(false);
  if (item.type == ItemType::kRgbNir14 && item.size == 8)
    return std::make_unique<RgbLayerDecoder>(true);
  if (item.type == ItemType::kByte14 && item.size > 0)
    return std::make_unique<BytesLayerDecoder>(item.size);
  return nullptr;
}

std::unique_ptr<LayerItemEncoder> make_layer_item_encoder(const Item& item) {
  if (item.version != 3) return nullptr;
  if (item.type == ItemType::kRgb14 && item.size == 6)
    return std::make_unique<RgbLayerEncoder>(false);
  if (item.type == ItemType::kRgbNir14 && item.size == 8)
    return std::make_unique<RgbLayerEncoder>(true);
  if (item.type == ItemType::kByte14 && item.size > 0)
    return std::make_unique<BytesLayerEncoder>(item.size);
  return nullptr;
}

}  // namespace ramus::laz
