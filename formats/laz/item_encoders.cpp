#include "formats/laz/item_encoders.h"

#include <cstring>
#include <limits>
#include <vector>

#include "formats/laz/gps_time_encoder.h"
#include "formats/laz/integer_encoder.h"
#include "formats/laz/rgb_coding.h"
#include "formats/laz/v2_tables.h"

namespace ramus::laz {
namespace {

// Mirror of Point10Decoder (item_decoders.cpp): same contexts, same predictions.
class Point10Encoder final : public ItemEncoder {
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
  }

  void encode(RangeEncoder& enc, const std::uint8_t* item) override {
    const std::uint32_t r = item[14] & 7, n = (item[14] >> 3) & 7;
    const std::uint32_t m = kReturnContext[n][r], l = return_level(n, r);
    const std::uint16_t intensity = get_le<std::uint16_t>(item + 12);
    const std::uint32_t changed =
        (std::uint32_t(last_[14] != item[14]) << 5) |
        (std::uint32_t(last_intensity_[m] != intensity) << 4) |
        (std::uint32_t(last_[15] != item[15]) << 3) | (std::uint32_t(last_[16] != item[16]) << 2) |
        (std::uint32_t(last_[17] != item[17]) << 1) |
        std::uint32_t(get_le<std::uint16_t>(last_ + 18) != get_le<std::uint16_t>(item + 18));
    enc.encode_symbol(changed_, changed);
    if (changed & 32) enc.encode_symbol(model(bit_byte_, last_[14]), item[14]);
    if (changed & 16) {
      intensity_.encode(enc, last_intensity_[m], intensity, m < 3 ? m : 3);
      last_intensity_[m] = intensity;
    }
    if (changed & 8) enc.encode_symbol(model(classification_, last_[15]), item[15]);
    if (changed & 4) {
      enc.encode_symbol(scan_angle_[(item[14] >> 6) & 1],
                        fold_u8(std::int32_t(item[16]) - std::int32_t(last_[16])));
    }
    if (changed & 2) enc.encode_symbol(model(user_data_, last_[17]), item[17]);
    if (changed & 1) {
      source_.encode(enc, get_le<std::uint16_t>(last_ + 18), get_le<std::uint16_t>(item + 18));
    }

    const std::int32_t dx =
        std::int32_t(get_le<std::uint32_t>(item) - get_le<std::uint32_t>(last_));
    dx_.encode(enc, dx_median_[m].get(), dx, n == 1);
    dx_median_[m].add(dx);

    std::uint32_t k = dx_.k();
    const std::int32_t dy =
        std::int32_t(get_le<std::uint32_t>(item + 4) - get_le<std::uint32_t>(last_ + 4));
    dy_.encode(enc, dy_median_[m].get(), dy, (n == 1) + (k < 20 ? k & ~1u : 20));
    dy_median_[m].add(dy);

    k = (dx_.k() + dy_.k()) / 2;
    const std::int32_t z = get_le<std::int32_t>(item + 8);
    z_.encode(enc, last_height_[l], z, (n == 1) + (k < 18 ? k & ~1u : 18));
    last_height_[l] = z;
    std::memcpy(last_, item, 20);
  }

 private:
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
  IntegerEncoder intensity_{16, 4};
  SymbolModel scan_angle_[2] = {SymbolModel(256), SymbolModel(256)};
  IntegerEncoder source_{16};
  std::vector<std::unique_ptr<SymbolModel>> bit_byte_, classification_, user_data_;
  IntegerEncoder dx_{32, 2}, dy_{32, 22}, z_{32, 20};
};

// GPS time (the double's bits), the codes of GpsTime11Decoder (gps_time_encoder.h).
class GpsTime11Encoder final : public ItemEncoder {
 public:
  void init(const std::uint8_t* raw) override {
    multi_.reset();
    zero_diff_.reset();
    ic_.reset();
    seq_.reset(get_le<std::uint64_t>(raw));
  }
  void encode(RangeEncoder& enc, const std::uint8_t* item) override {
    encode_gps_time(enc, multi_, zero_diff_, ic_, seq_, get_le<std::uint64_t>(item), false);
  }

 private:
  GpsSequences seq_;
  SymbolModel multi_{516};
  SymbolModel zero_diff_{6};
  IntegerEncoder ic_{32, 9};
};

// Mirror of Rgb12Decoder.
class Rgb12Encoder final : public ItemEncoder {
 public:
  void init(const std::uint8_t* raw) override {
    models_.reset();
    for (int i = 0; i < 3; ++i) last_[i] = get_le<std::uint16_t>(raw + 2 * i);
  }
  void encode(RangeEncoder& enc, const std::uint8_t* item) override {
    std::uint16_t rgb[3];
    for (int i = 0; i < 3; ++i) rgb[i] = get_le<std::uint16_t>(item + 2 * i);
    encode_rgb(enc, models_, last_, rgb);
    for (int i = 0; i < 3; ++i) last_[i] = rgb[i];
  }

 private:
  std::uint16_t last_[3] = {};
  RgbModels models_;
};

class BytesEncoder final : public ItemEncoder {
 public:
  explicit BytesEncoder(std::size_t n) : last_(n), models_(n, SymbolModel(256)) {}
  void init(const std::uint8_t* raw) override {
    for (auto& m : models_) m.reset();
    std::memcpy(last_.data(), raw, last_.size());
  }
  void encode(RangeEncoder& enc, const std::uint8_t* item) override {
    for (std::size_t i = 0; i < last_.size(); ++i) {
      enc.encode_symbol(models_[i], fold_u8(std::int32_t(item[i]) - std::int32_t(last_[i])));
    }
    std::memcpy(last_.data(), item, last_.size());
  }

 private:
  std::vector<std::uint8_t> last_;
  std::vector<SymbolModel> models_;
};

}  // namespace

std::unique_ptr<ItemEncoder> make_v2_encoder(const Item& item) {
  if (item.version != 2) return nullptr;
  switch (item.type) {
    case ItemType::kPoint10:
      return item.size == 20 ? std::make_unique<Point10Encoder>() : nullptr;
    case ItemType::kGpsTime11:
      return item.size == 8 ? std::make_unique<GpsTime11Encoder>() : nullptr;
    case ItemType::kRgb12:
      return item.size == 6 ? std::make_unique<Rgb12Encoder>() : nullptr;
    case ItemType::kByte:
      return item.size > 0 ? std::make_unique<BytesEncoder>(item.size) : nullptr;
    default:
      return nullptr;
  }
}

}  // namespace ramus::laz
