// The state of LASzip's layered point14 coder (version 3, LAS 1.4 point formats 6-10;
// Isenburg, "LASzip for LAS 1.4", 2017): the point split into nine layers, each range coded
// into its own stream (returns and x/y, z, classification, flags, intensity, scan angle, user
// data, point source, GPS time), with one set of models per scanner channel. Shared by the
// decoder and the encoder, which differ only in the integer coder type.
#pragma once

#include <array>
#include <cstdint>
#include <memory>

#include "formats/laz/adaptive_models.h"
#include "formats/laz/gps_sequences.h"
#include "formats/laz/v2_tables.h"

namespace ramus::laz {

// A point format 6 record's core fields (30 bytes).
struct Point14 {
  std::int32_t x = 0, y = 0, z = 0;
  std::uint16_t intensity = 0;
  std::uint8_t r = 0, n = 0;  // return number, number of returns (4 bits each)
  std::uint8_t flags = 0;     // classification flags (4 bits), scan direction, edge of flight line
  std::uint8_t channel = 0;   // scanner channel (2 bits)
  std::uint8_t cls = 0, user = 0;
  std::int16_t angle = 0;
  std::uint16_t source = 0;
  std::uint64_t gps = 0;  // the double's bits
  bool gps_changed = false;

  static Point14 unpack(const std::uint8_t* b);
  void pack(std::uint8_t* b) const;
};

// The layers of a point14 chunk, in stream order.
enum Layer14 {
  kReturnsXY,
  kZ,
  kClass,
  kFlags,
  kIntensity,
  kAngle,
  kUser,
  kSource,
  kGps,
  kLayers14
};

// Context tables of the version 3 coder: 6 return contexts for x/y, 8 return levels for z.
std::uint32_t return_context6(std::uint32_t n, std::uint32_t r);
inline std::uint32_t return_level8(std::uint32_t n, std::uint32_t r) {
  const std::uint32_t d = n > r ? n - r : r - n;
  return d < 7 ? d : 7;
}

inline constexpr std::int32_t kGps14Multi = 500, kGps14MultiMinus = -10;
inline constexpr std::int32_t kGps14CodeFull = kGps14Multi - kGps14MultiMinus + 1;  // 511
inline constexpr std::uint32_t kGps14Total = kGps14Multi - kGps14MultiMinus + 5;    // 515

template <typename IntCoder>
struct Point14Context {
  bool unused = true;
  Point14 last;
  std::array<SymbolModel, 8> changed = make<8>(128);
  SymbolModel channel{3};
  std::array<std::unique_ptr<SymbolModel>, 16> n_models, r_models;
  SymbolModel r_gps_same{13};
  IntCoder dx{32, 2}, dy{32, 22}, z{32, 20};
  StreamingMedian5 dx_median[12], dy_median[12];
  std::int32_t last_z[8] = {};
  std::array<std::unique_ptr<SymbolModel>, 64> cls_models, flag_models, user_models;
  IntCoder intensity{16, 4};
  std::uint16_t last_intensity[8] = {};
  IntCoder angle{16, 2};
  IntCoder source{16};
  SymbolModel gps_multi{kGps14Total}, gps_zero_diff{5};
  IntCoder gps{32, 9};
  GpsSequences seq;

  // Makes the context current for a chunk or a new scanner channel, starting from `from`.
  void start(const Point14& from) {
    for (auto& m : changed) m.reset();
    channel.reset();
    for (auto* models : {&n_models, &r_models}) {
      for (auto& m : *models) {
        if (m) m->reset();
      }
    }
    r_gps_same.reset();
    dx.reset();
    dy.reset();
    for (int i = 0; i < 12; ++i) {
      dx_median[i].reset();
      dy_median[i].reset();
    }
    z.reset();
    for (auto& v : last_z) v = from.z;
    for (auto* models : {&cls_models, &flag_models, &user_models}) {
      for (auto& m : *models) {
        if (m) m->reset();
      }
    }
    intensity.reset();
    for (auto& v : last_intensity) v = from.intensity;
    angle.reset();
    source.reset();
    gps_multi.reset();
    gps_zero_diff.reset();
    gps.reset();
    seq.reset(from.gps);
    last = from;
    last.gps_changed = false;
    unused = false;
  }

  template <std::size_t N>
  static SymbolModel& lazy(std::array<std::unique_ptr<SymbolModel>, N>& models, std::size_t i,
                           std::uint32_t symbols) {
    auto& m = models[i];
    if (!m) m = std::make_unique<SymbolModel>(symbols);
    return *m;
  }

 private:
  template <std::size_t N>
  static std::array<SymbolModel, N> make(std::uint32_t symbols) {
    return make_impl<N>(symbols, std::make_index_sequence<N>{});
  }
  template <std::size_t N, std::size_t... I>
  static std::array<SymbolModel, N> make_impl(std::uint32_t s, std::index_sequence<I...>) {
    return {((void)I, SymbolModel(s))...};
  }
};

}  // namespace ramus::laz
