#include "formats/laz/layered_decoder.h"

#include <cstring>
#include <vector>

#include "formats/laz/integer_decoder.h"
#include "formats/laz/layered_items.h"
#include "formats/laz/point14_context.h"
#include "formats/laz/range_decoder.h"

namespace ramus::laz {
namespace {

using Context = Point14Context<IntegerDecoder>;

class Point14Layers final : public ChunkCodec {
 public:
  explicit Point14Layers(std::vector<std::unique_ptr<LayerItemDecoder>> items,
                         std::vector<std::size_t> sizes)
      : items_(std::move(items)), sizes_(std::move(sizes)) {
    record_ = 30;
    layers_ = kLayers14;
    for (std::size_t i = 0; i < items_.size(); ++i) {
      record_ += sizes_[i];
      layers_ += items_[i]->layers();
    }
    dec_.resize(layers_);
    present_.resize(layers_);
    layer_begin_.resize(layers_);
    layer_end_.resize(layers_);
  }

  void start(const std::uint8_t* begin, const std::uint8_t* end, std::size_t) override {
    begin_ = begin;
    end_ = end;
    first_ = true;
  }

  void next(std::uint8_t* out) override {
    if (first_) {
      first_ = false;
      start_chunk(out);
      return;
    }
    decode(out);
  }

 private:
  // First record raw; then u32 point count, u32 bytes per layer, the layers back to back.
  void start_chunk(std::uint8_t* out) {
    const std::size_t head = record_ + 4 + 4 * layers_;
    if (std::size_t(end_ - begin_) < head) throw StreamOverrun{};
    std::memcpy(out, begin_, record_);
    const std::uint8_t* p = begin_ + record_ + 4;
    const std::uint8_t* layer = begin_ + head;
    for (std::size_t i = 0; i < layers_; ++i) {
      const std::uint32_t size = get_le<std::uint32_t>(p + 4 * i);
      if (std::size_t(end_ - layer) < size) throw StreamOverrun{};
      present_[i] = size > 0 ? 1 : 0;
      layer_begin_[i] = layer;
      layer_end_[i] = layer + size;
      layer += size;
    }
    // The returns/XY layer is always there; the others only when their field changes.
    started_ = false;
    const Point14 first = Point14::unpack(out);
    for (auto& c : contexts_) c.unused = true;
    current_ = first.channel;
    contexts_[current_].start(first);
    std::size_t at = 30;
    for (std::size_t i = 0; i < items_.size(); at += sizes_[i++]) {
      items_[i]->start(out + at, current_);
    }
  }

  void decode(std::uint8_t* out) {
    if (!started_) {  // the streams start with the second point (a one-point chunk has none)
      for (std::size_t i = 0; i < layers_; ++i) {
        if (i == kReturnsXY || present_[i]) dec_[i].start(layer_begin_[i], layer_end_[i]);
      }
      started_ = true;
    }
    RangeDecoder& d = dec_[kReturnsXY];
    Context* c = &contexts_[current_];
    const Point14& prev = c->last;
    std::uint32_t lpr =
        (prev.r == 1 ? 1u : 0u) + (prev.r >= prev.n ? 2u : 0u) + (prev.gps_changed ? 4u : 0u);
    const std::uint32_t changed = d.decode_symbol(c->changed[lpr]);
    if (changed & 64) {  // another scanner channel: its own context, made from this point
      const std::uint32_t channel = (current_ + d.decode_symbol(c->channel) + 1) % 4;
      if (contexts_[channel].unused) contexts_[channel].start(c->last);
      current_ = channel;
      c = &contexts_[current_];
      c->last.channel = std::uint8_t(channel);
    }
    Point14& p = c->last;
    const bool source_changed = changed & 32, gps_changed = changed & 16,
               angle_changed = changed & 8;
    const std::uint32_t last_n = p.n, last_r = p.r;
    if (changed & 4) {
      p.n = std::uint8_t(d.decode_symbol(Context::lazy(c->n_models, last_n, 16)));
    }
    switch (changed & 3) {
      case 0:
        break;
      case 1:
        p.r = std::uint8_t((last_r + 1) % 16);
        break;
      case 2:
        p.r = std::uint8_t((last_r + 15) % 16);
        break;
      default:
        if (gps_changed) {
          p.r = std::uint8_t(d.decode_symbol(Context::lazy(c->r_models, last_r, 16)));
        } else {
          p.r = std::uint8_t((last_r + d.decode_symbol(c->r_gps_same) + 2) % 16);
        }
    }
    const std::uint32_t n = p.n, r = p.r;
    const std::uint32_t m = return_context6(n, r), l = return_level8(n, r);
    const std::uint32_t cpr = (r == 1 ? 1u : 0u) + (r >= n ? 2u : 0u);
    const std::uint32_t xy = (m << 1) | (gps_changed ? 1u : 0u);

    const std::int32_t dx = c->dx.decode(d, c->dx_median[xy].get(), n == 1);
    p.x = std::int32_t(std::uint32_t(p.x) + std::uint32_t(dx));
    c->dx_median[xy].add(dx);
    std::uint32_t k = c->dx.k();
    const std::int32_t dy =
        c->dy.decode(d, c->dy_median[xy].get(), (n == 1) + (k < 20 ? k & ~1u : 20));
    p.y = std::int32_t(std::uint32_t(p.y) + std::uint32_t(dy));
    c->dy_median[xy].add(dy);

    if (present_[kZ]) {
      k = (c->dx.k() + c->dy.k()) / 2;
      p.z = c->z.decode(dec_[kZ], c->last_z[l], (n == 1) + (k < 18 ? k & ~1u : 18));
      c->last_z[l] = p.z;
    }
    if (present_[kClass]) {
      const std::uint32_t ctx = ((p.cls & 0x1fu) << 1) + (cpr == 3 ? 1u : 0u);
      p.cls = std::uint8_t(dec_[kClass].decode_symbol(Context::lazy(c->cls_models, ctx, 256)));
    }
    if (present_[kFlags]) {
      p.flags =
          std::uint8_t(dec_[kFlags].decode_symbol(Context::lazy(c->flag_models, p.flags, 64)));
    }
    if (present_[kIntensity]) {
      const std::uint32_t at = (cpr << 1) | (gps_changed ? 1u : 0u);
      p.intensity =
          std::uint16_t(c->intensity.decode(dec_[kIntensity], c->last_intensity[at], cpr));
      c->last_intensity[at] = p.intensity;
    }
    if (present_[kAngle] && angle_changed) {
      p.angle = std::int16_t(c->angle.decode(dec_[kAngle], p.angle, gps_changed ? 1 : 0));
    }
    if (present_[kUser]) {
      p.user =
          std::uint8_t(dec_[kUser].decode_symbol(Context::lazy(c->user_models, p.user / 4, 256)));
    }
    if (present_[kSource] && source_changed) {
      p.source = std::uint16_t(c->source.decode(dec_[kSource], p.source));
    }
    if (present_[kGps] && gps_changed) {
      decode_gps(*c, dec_[kGps]);
      p.gps = c->seq.time[c->seq.last];
    }
    p.gps_changed = false;
    p.pack(out);
    p.gps_changed = gps_changed;
    std::size_t at = 30, layer = kLayers14;
    for (std::size_t i = 0; i < items_.size(); at += sizes_[i], layer += items_[i++]->layers()) {
      items_[i]->decode(&dec_[layer], &present_[layer], out + at, current_);
    }
  }

  // GPS times of the layered coder: like gpstime11 v2 without the "unchanged" code (the
  // returns layer says whether the time changed) and with a 5-symbol zero-difference model.
  static void decode_gps(Context& c, RangeDecoder& d) {
    for (;;) {
      std::uint32_t& last = c.seq.last;
      if (c.seq.diff[last] == 0) {
        const std::uint32_t multi = d.decode_symbol(c.gps_zero_diff);
        if (multi == 0) {
          c.seq.diff[last] = c.gps.decode(d, 0, 0);
          c.seq.time[last] += std::uint64_t(std::int64_t(c.seq.diff[last]));
          c.seq.extreme[last] = 0;
        } else if (multi == 1) {
          full_time(c, d);
        } else {
          last = (last + multi - 1) & 3;
          continue;
        }
        return;
      }
      const std::int32_t multi = std::int32_t(d.decode_symbol(c.gps_multi));
      if (multi == 1) {
        c.seq.time[last] += std::uint64_t(std::int64_t(c.gps.decode(d, c.seq.diff[last], 1)));
        c.seq.extreme[last] = 0;
      } else if (multi < kGps14CodeFull) {
        std::int32_t diff;
        auto times = [](std::int32_t a, std::int32_t b) {
          return std::int32_t(std::uint32_t(a) * std::uint32_t(b));
        };
        auto extreme = [&](std::int32_t v) {
          if (++c.seq.extreme[last] > 3) {
            c.seq.diff[last] = v;
            c.seq.extreme[last] = 0;
          }
        };
        if (multi == 0) {
          diff = c.gps.decode(d, 0, 7);
          extreme(diff);
        } else if (multi < kGps14Multi) {
          diff = c.gps.decode(d, times(multi, c.seq.diff[last]), multi < 10 ? 2 : 3);
        } else if (multi == kGps14Multi) {
          diff = c.gps.decode(d, times(kGps14Multi, c.seq.diff[last]), 4);
          extreme(diff);
        } else {
          const std::int32_t minus = kGps14Multi - multi;
          if (minus > kGps14MultiMinus) {
            diff = c.gps.decode(d, times(minus, c.seq.diff[last]), 5);
          } else {
            diff = c.gps.decode(d, times(kGps14MultiMinus, c.seq.diff[last]), 6);
            extreme(diff);
          }
        }
        c.seq.time[last] += std::uint64_t(std::int64_t(diff));
      } else if (multi == kGps14CodeFull) {
        full_time(c, d);
      } else {
        last = (last + std::uint32_t(multi - kGps14CodeFull)) & 3;
        continue;
      }
      return;
    }
  }

  static void full_time(Context& c, RangeDecoder& d) {
    c.seq.next = (c.seq.next + 1) & 3;
    const std::uint32_t high =
        std::uint32_t(c.gps.decode(d, std::int32_t(c.seq.time[c.seq.last] >> 32), 8));
    c.seq.time[c.seq.next] = (std::uint64_t(high) << 32) | d.read_int();
    c.seq.last = c.seq.next;
    c.seq.diff[c.seq.last] = 0;
    c.seq.extreme[c.seq.last] = 0;
  }

  std::vector<std::unique_ptr<LayerItemDecoder>> items_;  // after point14
  std::vector<std::size_t> sizes_;
  std::size_t record_ = 30, layers_ = kLayers14;
  const std::uint8_t* begin_ = nullptr;
  const std::uint8_t* end_ = nullptr;
  bool first_ = true, started_ = false;
  std::vector<std::uint8_t> present_;  // 1: the layer has bytes
  std::vector<const std::uint8_t*> layer_begin_, layer_end_;
  std::vector<RangeDecoder> dec_;
  Context contexts_[4];
  std::uint32_t current_ = 0;
};

}  // namespace

std::unique_ptr<ChunkCodec> make_layered_decoder(const LaszipVlr& vlr, std::string& why) {
  const auto& items = vlr.items;
  if (items.empty() || items[0].type != ItemType::kPoint14 || items[0].version != 3 ||
      items[0].size != 30) {
    why = "LAZ layered chunks must start with the point14 v3 item";
    return nullptr;
  }
  std::vector<std::unique_ptr<LayerItemDecoder>> rest;
  std::vector<std::size_t> sizes;
  for (std::size_t i = 1; i < items.size(); ++i) {
    auto d = make_layer_item_decoder(items[i]);
    if (!d) {
      why = "LAZ item " + item_name(items[i]) + " (" + std::to_string(items[i].size) +
            " bytes) is not supported";
      return nullptr;
    }
    rest.push_back(std::move(d));
    sizes.push_back(items[i].size);
  }
  return std::make_unique<Point14Layers>(std::move(rest), std::move(sizes));
}

}  // namespace ramus::laz
