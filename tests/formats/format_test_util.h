// Builders for synthetic point-cloud files in the formats tests: bytes in either endianness,
// LAS files of any version and point format, temporary folders.
#pragma once

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "formats/point_cloud_io.h"

namespace ramus::test {

class Bytes {
 public:
  explicit Bytes(bool big_endian = false) : big_(big_endian) {}
  template <typename T>
  Bytes& put(T v) {
    char b[sizeof(T)];
    std::memcpy(b, &v, sizeof(T));
    if (big_) {
      for (std::size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(b[i], b[sizeof(T) - 1 - i]);
    }
    s_.append(b, sizeof(T));
    return *this;
  }
  Bytes& text(const std::string& t) {
    s_ += t;
    return *this;
  }
  Bytes& zeros(std::size_t n) {
    s_.append(n, '\0');
    return *this;
  }
  std::string& str() { return s_; }

 private:
  bool big_;
  std::string s_;
};

// Writes a little-endian value at a fixed offset of an existing buffer.
template <typename T>
void poke(std::string& s, std::size_t at, T v) {
  std::memcpy(s.data() + at, &v, sizeof(T));
}

struct LasPoint {
  std::int32_t x = 0, y = 0, z = 0;
  std::uint16_t intensity = 0;
  std::uint8_t classification = 0;
};

// Minimum record length of LAS point formats 0-10.
inline std::size_t las_record_size(int format) {
  static const std::size_t sizes[] = {20, 28, 26, 34, 57, 63, 30, 36, 38, 59, 67};
  return sizes[format];
}

struct LasSpec {
  int minor = 2;
  int format = 0;
  std::size_t extra_bytes = 0;  // beyond the format's minimum record length
  double scale[3] = {0.001, 0.001, 0.001};
  double offset[3] = {0, 0, 0};
  int vlrs = 0;  // dummy VLRs before the points
  bool zero_legacy_count = false;
};

// A LAS file with the given points, laid out per the LAS 1.0-1.4 public header tables.
inline std::string make_las(const LasSpec& spec, const std::vector<LasPoint>& points) {
  const std::size_t header = spec.minor >= 4 ? 375 : spec.minor == 3 ? 235 : 227;
  const std::size_t record = las_record_size(spec.format) + spec.extra_bytes;
  std::string s(header, '\0');
  std::memcpy(s.data(), "LASF", 4);
  s[24] = 1;
  s[25] = char(spec.minor);
  std::memcpy(s.data() + 26, "ramus test", 10);
  poke<std::uint16_t>(s, 94, std::uint16_t(header));
  poke<std::uint32_t>(s, 96, std::uint32_t(header + std::size_t(spec.vlrs) * (54 + 8)));
  poke<std::uint32_t>(s, 100, std::uint32_t(spec.vlrs));
  s[104] = char(spec.format);
  poke<std::uint16_t>(s, 105, std::uint16_t(record));
  bool legacy = !spec.zero_legacy_count && spec.format < 6;
  poke<std::uint32_t>(s, 107, legacy ? std::uint32_t(points.size()) : 0u);
  for (int k = 0; k < 3; ++k) {
    poke<double>(s, 131 + 8 * k, spec.scale[k]);
    poke<double>(s, 155 + 8 * k, spec.offset[k]);
  }
  // Header bounding box deliberately left zero: readers must not trust it.
  if (spec.minor >= 4) poke<std::uint64_t>(s, 247, points.size());
  for (int v = 0; v < spec.vlrs; ++v) {
    Bytes b;
    b.put<std::uint16_t>(0).text(std::string("ramus_test\0\0\0\0\0\0", 16));
    b.put<std::uint16_t>(std::uint16_t(v)).put<std::uint16_t>(8).zeros(32).zeros(8);
    s += b.str();
  }
  for (const LasPoint& p : points) {
    std::string r(record, '\0');
    poke<std::int32_t>(r, 0, p.x);
    poke<std::int32_t>(r, 4, p.y);
    poke<std::int32_t>(r, 8, p.z);
    poke<std::uint16_t>(r, 12, p.intensity);
    if (spec.format >= 6) {
      r[16] = char(p.classification);
    } else {
      r[15] = char(p.classification | 0xe0);  // flags in bits 5-7 must be masked off
    }
    for (std::size_t i = las_record_size(spec.format); i < record; ++i) r[i] = char(0xab);
    s += r;
  }
  return s;
}

inline std::filesystem::path temp_dir(const std::string& name) {
  auto dir = std::filesystem::temp_directory_path() / ("ramus_formats_" + name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

inline std::string shared_data(const std::string& file) {
  return std::string(RAMUS_SHARED_DIR) + "/data/" + file;
}

// The message of the FormatError `f` throws ("" when it does not throw).
template <typename F>
std::string error_of(F&& f) {
  try {
    f();
  } catch (const FormatError& e) {
    return e.what();
  }
  return "";
}

}  // namespace ramus::test
