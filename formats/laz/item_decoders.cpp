#include "formats/laz/item_decoders.h"

#include <cstring>
#include <vector>

#include "formats/laz/integer_decoder.h"
#include "formats/laz/rgb_coding.h"
#include "formats/laz/v2_tables.h"

namespace ramus::laz {

void StreamingMedian5::add(std::int32_t v) {
  // Alternately drops the largest (high_) or the smallest value and inserts v in order, so the
  // middle slot follows the median of the recent values without sorting.
  if (high_) {
    if (v < v_[2]) {
      v_[4] = v_[3];
      v_[3] = v_[2];
      if (v < v_[0]) {
        v_[2] = v_[1];
        v_[1] = v_[0];
        v_[0] = v;
      } else if (v < v_[1]) {
        v_[2] = v_[1];
        v_[1] = v;
      } else {
        v_[2] = v;
      }
    } else {
      if (v < v_[3]) {
        v_[4] = v_[3];
        v_[3] = v;
      } else {
        v_[4] = v;
      }
      high_ = false;
    }
  } else {
    if (v_[2] < v) {
      v_[0] = v_[1];
      v_[1] = v_[2];
      if (v_[4] < v) {
        v_[2] = v_[3];
        v_[3] = v_[4];
        v_[4] = v;
      } else if (v_[3] < v) {
        v_[2] = v_[3];
        v_[3] = v;
      } else {
        v_[2] = v;
      }
    } else {
      if (v_[1] < v) {
        v_[0] = v_[1];
        v_[1] = v;
      } else {
        v_[0] = v;
      }
      high_ = true;
    }
  }
}

namespace {

// Point10 (x, y, z, intensity, return bits, class, scan angle, user data, point source; 20
// bytes). A 6-bit mask says which of the non-coordinate fields changed; x and y are predicted
// by the median of the last five differences of the same return context, z by the last height
// of the same return level (Isenburg 2013, section 4.1).
class Point10Decoder final : public ItemDecoder {
 public:
  void init(const std::uint8_t* raw) override {
    for (int i = 0; i < 16; ++i) {
      dx_median_[i].reset();
      dy_median_[i].reset();
      last_intensity_[i] = 0;
    }
    for (auto& h : last_height_) h = 0;
    changed_.reset();
    intensity_.reset();
    scan_angle_[0].reset();
    scan_angle_[1].reset();
    source_.reset();
    for (auto* models : {&bit_byte_, &classification_, &user_data_}) {
      for (auto& m : *models) {
        if (m) m->reset();
      }
    }
    dx_.reset();
    dy_.reset();
    z_.reset();
    std::memcpy(last_, raw, 20);
    last_[12] = last_[13] = 0;  // the intensity is coded against 0 at a chunk's start
  }

  void decode(RangeDecoder& dec, std::uint8_t* out) override {
    const std::uint32_t changed = dec.decode_symbol(changed_);
    if (changed & 32) last_[14] = std::uint8_t(dec.decode_symbol(model(bit_byte_, last_[14])));
    const std::uint32_t r = last_[14] & 7, n = (last_[14] >> 3) & 7;
    const std::uint32_t m = kReturnContext[n][r], l = return_level(n, r);
    if (changed & 16) {
      last_intensity_[m] = std::uint16_t(intensity_.decode(dec, last_intensity_[m], m < 3 ? m : 3));
    }
    put_le<std::uint16_t>(last_ + 12, last_intensity_[m]);
    if (changed & 8) {
      last_[15] = std::uint8_t(dec.decode_symbol(model(classification_, last_[15])));
    }
    if (changed & 4) {
      const std::uint32_t delta = dec.decode_symbol(scan_angle_[(last_[14] >> 6) & 1]);
      last_[16] = fold_u8(std::int32_t(delta + last_[16]));
    }
    if (changed & 2) last_[17] = std::uint8_t(dec.decode_symbol(model(user_data_, last_[17])));
    if (changed & 1) {
      put_le<std::uint16_t>(last_ + 18,
                            std::uint16_t(source_.decode(dec, get_le<std::uint16_t>(last_ + 18))));
    }

    const std::int32_t dx = dx_.decode(dec, dx_median_[m].get(), n == 1);
    put_le<std::uint32_t>(last_, get_le<std::uint32_t>(last_) + std::uint32_t(dx));
    dx_median_[m].add(dx);

    std::uint32_t k = dx_.k();
    const std::int32_t dy =
        dy_.decode(dec, dy_median_[m].get(), (n == 1) + (k < 20 ? k & ~1u : 20));
    put_le<std::uint32_t>(last_ + 4, get_le<std::uint32_t>(last_ + 4) + std::uint32_t(dy));
    dy_median_[m].add(dy);

    k = (dx_.k() + dy_.k()) / 2;
    last_height_[l] = z_.decode(dec, last_height_[l], (n == 1) + (k < 18 ? k & ~1u : 18));
    put_le<std::int32_t>(last_ + 8, last_height_[l]);
    std::memcpy(out, last_, 20);
  }

 private:
  // Models of byte fields are made on first use, one per previous value of the field.
  static SymbolModel& model(std::vector<std::unique_ptr<SymbolModel>>& models, std::uint8_t prev) {
    if (models.empty()) models.resize(256);
    auto& m = models[prev];
    if (!m) m = std::make_unique<SymbolModel>(256);
    return *m;
  }

  std::uint8_t last_[20] = {};
  std::uint16_t last_intensity_[16] = {};
  StreamingMedian5 dx_median_[16], dy_median_[16];
  std::int32_t last_height_[8] = {};
  SymbolModel changed_{64};
  IntegerDecoder intensity_{16, 4};
  SymbolModel scan_angle_[2] = {SymbolModel(256), SymbolModel(256)};
  IntegerDecoder source_{16};
  std::vector<std::unique_ptr<SymbolModel>> bit_byte_, classification_, user_data_;
  IntegerDecoder dx_{32, 2}, dy_{32, 22}, z_{32, 20};
};

// GPS time (a double, 8 bytes), coded as integer differences of its bit pattern. Up to four
// interleaved sequences are tracked (multiple returns, several scanners); each difference is a
// multiple of the sequence's last difference plus a correction (Isenburg 2013, section 4.2).
class GpsTime11Decoder final : public ItemDecoder {
 public:
  static constexpr std::int32_t kMulti = 500, kMultiMinus = -10;
  static constexpr std::int32_t kMultiUnchanged = kMulti - kMultiMinus + 1;
  static constexpr std::int32_t kMultiCodeFull = kMulti - kMultiMinus + 2;
  static constexpr std::int32_t kMultiTotal = kMulti - kMultiMinus + 6;

  void init(const std::uint8_t* raw) override {
    last_ = next_ = 0;
    for (int i = 0; i < 4; ++i) {
      diff_[i] = 0;
      extreme_[i] = 0;
      time_[i] = 0;
    }
    multi_.reset();
    zero_diff_.reset();
    ic_.reset();
    time_[0] = get_le<std::uint64_t>(raw);
  }

  void decode(RangeDecoder& dec, std::uint8_t* out) override {
    // A "switch to sequence j" code is followed by the code of this point in sequence j.
    for (;;) {
      if (diff_[last_] == 0) {
        const std::uint32_t multi = dec.decode_symbol(zero_diff_);
        if (multi == 1) {
          diff_[last_] = ic_.decode(dec, 0, 0);
          time_[last_] += std::uint64_t(std::int64_t(diff_[last_]));
          extreme_[last_] = 0;
        } else if (multi == 2) {
          full_time(dec);
        } else if (multi > 2) {
          last_ = (last_ + multi - 2) & 3;
          continue;
        }
      } else {
        const std::int32_t multi = std::int32_t(dec.decode_symbol(multi_));
        if (multi == 1) {
          time_[last_] += std::uint64_t(std::int64_t(ic_.decode(dec, diff_[last_], 1)));
          extreme_[last_] = 0;
        } else if (multi < kMultiUnchanged) {
          std::int32_t diff;
          if (multi == 0) {
            diff = ic_.decode(dec, 0, 7);
            extreme(diff);
          } else if (multi < kMulti) {
            diff = ic_.decode(dec, times(multi, diff_[last_]), multi < 10 ? 2 : 3);
          } else if (multi == kMulti) {
            diff = ic_.decode(dec, times(kMulti, diff_[last_]), 4);
            extreme(diff);
          } else {
            const std::int32_t minus = kMulti - multi;
            if (minus > kMultiMinus) {
              diff = ic_.decode(dec, times(minus, diff_[last_]), 5);
            } else {
              diff = ic_.decode(dec, times(kMultiMinus, diff_[last_]), 6);
              extreme(diff);
            }
          }
          time_[last_] += std::uint64_t(std::int64_t(diff));
        } else if (multi == kMultiCodeFull) {
          full_time(dec);
        } else if (multi > kMultiCodeFull) {
          last_ = (last_ + std::uint32_t(multi - kMultiCodeFull)) & 3;
          continue;
        }
      }
      break;
    }
    put_le<std::uint64_t>(out, time_[last_]);
  }

 private:
  // The product the format computes in 32-bit integers, wrapping like the reference coder.
  static std::int32_t times(std::int32_t a, std::int32_t b) {
    return std::int32_t(std::uint32_t(a) * std::uint32_t(b));
  }
  // An unusually large or small multiple: after more than three in a row it becomes the
  // sequence's new difference.
  void extreme(std::int32_t diff) {
    if (++extreme_[last_] > 3) {
      diff_[last_] = diff;
      extreme_[last_] = 0;
    }
  }
  // A new sequence starting from a full 64-bit time: upper half predicted from the current one.
  void full_time(RangeDecoder& dec) {
    next_ = (next_ + 1) & 3;
    const std::uint32_t high = std::uint32_t(ic_.decode(dec, std::int32_t(time_[last_] >> 32), 8));
    time_[next_] = (std::uint64_t(high) << 32) | dec.read_int();
    last_ = next_;
    diff_[last_] = 0;
    extreme_[last_] = 0;
  }

  std::uint32_t last_ = 0, next_ = 0;
  std::uint64_t time_[4] = {};
  std::int32_t diff_[4] = {};
  std::int32_t extreme_[4] = {};
  SymbolModel multi_{kMultiTotal};
  SymbolModel zero_diff_{6};
  IntegerDecoder ic_{32, 9};
};

// RGB (three u16, 6 bytes), see rgb_coding.h.
class Rgb12Decoder final : public ItemDecoder {
 public:
  void init(const std::uint8_t* raw) override {
    models_.reset();
    for (int i = 0; i < 3; ++i) last_[i] = get_le<std::uint16_t>(raw + 2 * i);
  }
  void decode(RangeDecoder& dec, std::uint8_t* out) override {
    decode_rgb(dec, models_, last_, last_);
    for (int i = 0; i < 3; ++i) put_le<std::uint16_t>(out + 2 * i, last_[i]);
  }

 private:
  std::uint16_t last_[3] = {};
  RgbModels models_;
};

// Extra bytes: each byte's difference to the previous point's byte, one model per byte.
class BytesDecoder final : public ItemDecoder {
 public:
  explicit BytesDecoder(std::size_t n) : last_(n), models_(n, SymbolModel(256)) {}
  void init(const std::uint8_t* raw) override {
    for (auto& m : models_) m.reset();
    std::memcpy(last_.data(), raw, last_.size());
  }
  void decode(RangeDecoder& dec, std::uint8_t* out) override {
    for (std::size_t i = 0; i < last_.size(); ++i) {
      last_[i] = fold_u8(std::int32_t(last_[i] + dec.decode_symbol(models_[i])));
    }
    std::memcpy(out, last_.data(), last_.size());
  }

 private:
  std::vector<std::uint8_t> last_;
  std::vector<SymbolModel> models_;
};

}  // namespace

std::unique_ptr<ItemDecoder> make_v2_decoder(const Item& item) {
  if (item.version != 2) return nullptr;
  switch (item.type) {
    case ItemType::kPoint10:
      return item.size == 20 ? std::make_unique<Point10Decoder>() : nullptr;
    case ItemType::kGpsTime11:
      return item.size == 8 ? std::make_unique<GpsTime11Decoder>() : nullptr;
    case ItemType::kRgb12:
      return item.size == 6 ? std::make_unique<Rgb12Decoder>() : nullptr;
    case ItemType::kByte:
      return item.size > 0 ? std::make_unique<BytesDecoder>(item.size) : nullptr;
    default:
      return nullptr;
  }
}

}  // namespace ramus::laz
