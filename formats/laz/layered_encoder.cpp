#include "formats/laz/layered_encoder.h"

#include <array>
#include <cstring>
#include <limits>
#include <memory>

#include "formats/laz/gps_time_encoder.h"
#include "formats/laz/integer_encoder.h"
#include "formats/laz/layered_items.h"
#include "formats/laz/point14_context.h"
#include "formats/laz/range_encoder.h"

namespace ramus::laz {
namespace {

using Context = Point14Context<IntegerEncoder>;

class Point14Encoder {
 public:
  explicit Point14Encoder(const Point14& first) {
    for (auto& b : bytes_) b.clear();
    for (int i = 0; i < kLayers14; ++i) enc_[i] = std::make_unique<RangeEncoder>(bytes_[i]);
    current_ = first.channel;
    contexts_[current_].start(first);
  }

  void encode(const Point14& item) {
    RangeEncoder& e = *enc_[kReturnsXY];
    Context* c = &contexts_[current_];
    const Point14& prev = c->last;
    const std::uint32_t lpr =
        (prev.r == 1 ? 1u : 0u) + (prev.r >= prev.n ? 2u : 0u) + (prev.gps_changed ? 4u : 0u);
    // Changes are judged against the last point of the item's own channel (or, for a channel
    // not seen yet in this chunk, against the point its context will be made from).
    const bool channel_changed = item.channel != current_;
    const Point14& ref =
        channel_changed && !contexts_[item.channel].unused ? contexts_[item.channel].last : c->last;
    const bool source_changed = item.source != ref.source, gps_changed = item.gps != ref.gps,
               angle_changed = item.angle != ref.angle;
    const std::uint32_t last_n = ref.n, last_r = ref.r, n = item.n, r = item.r;
    std::uint32_t changed = (std::uint32_t(channel_changed) << 6) |
                            (std::uint32_t(source_changed) << 5) |
                            (std::uint32_t(gps_changed) << 4) |
                            (std::uint32_t(angle_changed) << 3) | (std::uint32_t(n != last_n) << 2);
    if (r != last_r) {
      if (r == (last_r + 1) % 16) {
        changed |= 1;
      } else if (r == (last_r + 15) % 16) {
        changed |= 2;
      } else {
        changed |= 3;
      }
    }
    e.encode_symbol(c->changed[lpr], changed);
    if (channel_changed) {
      e.encode_symbol(c->channel, (item.channel + 4 - current_ - 1) % 4);
      if (contexts_[item.channel].unused) contexts_[item.channel].start(c->last);
      current_ = item.channel;
      c = &contexts_[current_];
      c->last.channel = item.channel;
    }
    Point14& p = c->last;
    if (changed & 4) e.encode_symbol(Context::lazy(c->n_models, last_n, 16), n);
    if ((changed & 3) == 3) {
      if (gps_changed) {
        e.encode_symbol(Context::lazy(c->r_models, last_r, 16), r);
      } else {
        e.encode_symbol(c->r_gps_same, (r + 16 - last_r - 2) % 16);
      }
    }
    const std::uint32_t m = return_context6(n, r), l = return_level8(n, r);
    const std::uint32_t cpr = (r == 1 ? 1u : 0u) + (r >= n ? 2u : 0u);
    const std::uint32_t xy = (m << 1) | (gps_changed ? 1u : 0u);

    const std::int32_t dx = std::int32_t(std::uint32_t(item.x) - std::uint32_t(p.x));
    c->dx.encode(e, c->dx_median[xy].get(), dx, n == 1);
    c->dx_median[xy].add(dx);
    std::uint32_t k = c->dx.k();
    const std::int32_t dy = std::int32_t(std::uint32_t(item.y) - std::uint32_t(p.y));
    c->dy.encode(e, c->dy_median[xy].get(), dy, (n == 1) + (k < 20 ? k & ~1u : 20));
    c->dy_median[xy].add(dy);

    k = (c->dx.k() + c->dy.k()) / 2;
    changed_[kZ] |= item.z != p.z;
    c->z.encode(*enc_[kZ], c->last_z[l], item.z, (n == 1) + (k < 18 ? k & ~1u : 18));
    c->last_z[l] = item.z;

    changed_[kClass] |= item.cls != p.cls;
    const std::uint32_t cls_ctx = ((p.cls & 0x1fu) << 1) + (cpr == 3 ? 1u : 0u);
    enc_[kClass]->encode_symbol(Context::lazy(c->cls_models, cls_ctx, 256), item.cls);

    changed_[kFlags] |= item.flags != p.flags;
    enc_[kFlags]->encode_symbol(Context::lazy(c->flag_models, p.flags, 64), item.flags);

    changed_[kIntensity] |= item.intensity != p.intensity;
    const std::uint32_t at = (cpr << 1) | (gps_changed ? 1u : 0u);
    c->intensity.encode(*enc_[kIntensity], c->last_intensity[at], item.intensity, cpr);
    c->last_intensity[at] = item.intensity;

    if (angle_changed) {
      changed_[kAngle] = true;
      c->angle.encode(*enc_[kAngle], p.angle, item.angle, gps_changed ? 1 : 0);
    }
    changed_[kUser] |= item.user != p.user;
    enc_[kUser]->encode_symbol(Context::lazy(c->user_models, p.user / 4, 256), item.user);
    if (source_changed) {
      changed_[kSource] = true;
      c->source.encode(*enc_[kSource], p.source, item.source);
    }
    if (gps_changed) {
      changed_[kGps] = true;
      encode_gps(*c, *enc_[kGps], item.gps);
    }
    p = item;
    p.channel = std::uint8_t(current_);
    p.gps_changed = gps_changed;
  }

  std::uint32_t channel() const { return current_; }

  // The nine layers; unchanged layers empty.
  void finish(std::vector<std::vector<std::uint8_t>>& layers) {
    changed_[kReturnsXY] = true;
    for (int i = 0; i < kLayers14; ++i) {
      enc_[i]->finish();
      layers.push_back(changed_[i] ? bytes_[i] : std::vector<std::uint8_t>{});
    }
  }

 private:
  static void encode_gps(Context& c, RangeEncoder& e, std::uint64_t t) {
    encode_gps_time(e, c.gps_multi, c.gps_zero_diff, c.gps, c.seq, t, true);
  }

  std::array<std::vector<std::uint8_t>, kLayers14> bytes_;
  std::array<std::unique_ptr<RangeEncoder>, kLayers14> enc_;
  bool changed_[kLayers14] = {};
  Context contexts_[4];
  std::uint32_t current_ = 0;
};

void append(std::vector<std::uint8_t>& out, std::uint32_t v) {
  std::uint8_t b[4];
  std::memcpy(b, &v, 4);
  out.insert(out.end(), b, b + 4);
}

}  // namespace

bool layered_items_supported(const std::vector<Item>& items) {
  if (items.empty() || items[0].type != ItemType::kPoint14 || items[0].version != 3) return false;
  for (std::size_t i = 1; i < items.size(); ++i) {
    if (!make_layer_item_encoder(items[i])) return false;
  }
  return true;
}

void encode_layered_chunk(const std::vector<Item>& items, const std::uint8_t* records,
                          std::size_t n, std::vector<std::uint8_t>& out) {
  if (n == 0) return;
  std::size_t record = 0;
  for (const auto& item : items) record += item.size;
  out.insert(out.end(), records, records + record);
  const Point14 first = Point14::unpack(records);
  Point14Encoder point(first);
  std::vector<std::unique_ptr<LayerItemEncoder>> rest;
  std::vector<std::size_t> offsets;
  std::size_t at = 30;
  for (std::size_t i = 1; i < items.size(); at += items[i++].size) {
    rest.push_back(make_layer_item_encoder(items[i]));
    offsets.push_back(at);
    rest.back()->start(records + at, first.channel);
  }
  for (std::size_t k = 1; k < n; ++k) {
    const std::uint8_t* rec = records + k * record;
    point.encode(Point14::unpack(rec));
    for (std::size_t i = 0; i < rest.size(); ++i)
      rest[i]->encode(rec + offsets[i], point.channel());
  }
  std::vector<std::vector<std::uint8_t>> layers;
  point.finish(layers);
  for (auto& r : rest) r->finish(layers);
  if (n < 2) {
    for (auto& l : layers) l.clear();  // a one-point chunk needs no streams
  }
  append(out, std::uint32_t(n));
  for (const auto& l : layers) append(out, std::uint32_t(l.size()));
  for (const auto& l : layers) out.insert(out.end(), l.begin(), l.end());
}

}  // namespace ramus::laz
