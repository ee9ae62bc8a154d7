// LAS 1.4 writer (header layout: LAS 1.4 R15 public header block, table 3; point formats 0 and
// 6, tables 7 and 13; Extra Bytes VLR, section 2.16) and, through formats/laz/, LAZ.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>

#include "core/atomic_file.h"
#include "formats/detail/reader_util.h"
#include "formats/las_file.h"
#include "formats/laz/laz_writer.h"

namespace ramus {
namespace {

template <typename T>
void put(std::string& s, std::size_t at, T v) {
  std::memcpy(s.data() + at, &v, sizeof v);
}
template <typename T>
void append(std::string& s, T v) {
  char b[sizeof v];
  std::memcpy(b, &v, sizeof v);
  s.append(b, sizeof v);
}
// A fixed-size, zero-padded text field.
void append_text(std::string& s, std::string_view text, std::size_t size) {
  std::string f(text.substr(0, size));
  f.resize(size, '\0');
  s += f;
}

std::string vlr(std::string_view user, std::uint16_t id, std::string_view description,
                const std::string& payload) {
  std::string s;
  append<std::uint16_t>(s, 0);  // reserved
  append_text(s, user, 16);
  append<std::uint16_t>(s, id);
  append<std::uint16_t>(s, std::uint16_t(payload.size()));
  append_text(s, description, 32);
  return s + payload;
}

// One 192-byte descriptor of the Extra Bytes VLR: data type 1 (u8) or 9 (f32), no options.
std::string extra_bytes_descriptor(const LasExtraBytes& e) {
  std::string s;
  append<std::uint16_t>(s, 0);
  append<std::uint8_t>(s, e.f32.empty() ? 1 : 9);
  append<std::uint8_t>(s, 0);
  append_text(s, e.name, 32);
  s.append(4 + 24 * 5, '\0');  // unused, no_data, min, max, scale, offset
  append_text(s, e.description, 32);
  return s;
}

double pick_scale(const PointCloud& c, double wanted) {
  double reach = 0;
  for (const auto& p : c.positions) {
    for (int k = 0; k < 3; ++k) reach = std::max(reach, std::abs(double(p[k])));
  }
  double scale = wanted > 0 ? wanted : 1e-4;
  if (wanted > 0 && reach / scale > 2147483000.0) {
    throw WriteError("a LAS scale of " + std::to_string(wanted) + " m cannot hold coordinates " +
                     std::to_string(reach) + " m from the offset in 32-bit integers");
  }
  while (reach / scale > 2147483000.0) scale *= 10;
  return scale;
}

}  // namespace

std::string point_cloud_to_las(const PointCloud& cloud, const LasWriteOptions& o) {
  const std::size_t n = cloud.size();
  std::size_t extra = 0;
  for (const auto& e : o.extra) {
    const std::size_t values = e.f32.empty() ? e.u8.size() : e.f32.size();
    if (values != n || (!e.f32.empty() && !e.u8.empty())) {
      throw std::invalid_argument("LAS extra bytes '" + e.name + "' need one value per point");
    }
    extra += e.f32.empty() ? 1 : 4;
  }
  constexpr unsigned format = 6;
  const std::size_t record = 30 + extra;
  const double scale = pick_scale(cloud, o.scale);

  // The records, and the bounds of the coordinates as written.
  std::string points(n * record, '\0');
  std::int32_t lo[3] = {INT32_MAX, INT32_MAX, INT32_MAX}, hi[3] = {INT32_MIN, INT32_MIN, INT32_MIN};
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t r = i * record;
    for (int k = 0; k < 3; ++k) {
      const std::int32_t v = std::int32_t(std::llround(double(cloud.positions[i][k]) / scale));
      put(points, r + 4 * k, v);
      lo[k] = std::min(lo[k], v);
      hi[k] = std::max(hi[k], v);
    }
    const float in = cloud.intensity.empty() ? 0.f : cloud.intensity[i];
    put<std::uint16_t>(points, r + 12, std::uint16_t(std::clamp(std::lround(in), 0l, 65535l)));
    points[r + 14] = char(0x11);  // return 1 of 1
    points[r + 16] = char(cloud.classification.empty() ? 0 : cloud.classification[i]);
    std::size_t at = r + record - extra;
    for (const auto& e : o.extra) {
      if (e.f32.empty()) {
        points[at++] = char(e.u8[i]);
      } else {
        put(points, at, e.f32[i]);
        at += 4;
      }
    }
  }

  std::string vlrs;
  std::uint32_t vlr_count = 0;
  if (!o.extra.empty()) {
    std::string d;
    for (const auto& e : o.extra) d += extra_bytes_descriptor(e);
    vlrs += vlr("LASF_Spec", 4, "extra bytes", d);
    ++vlr_count;
  }
  laz::LaszipVlr laz_vlr;
  if (o.compressed) {
    laz::v2_items(format, record, laz_vlr);
    vlrs += vlr("laszip encoded", 22204, "ramus LAZ (layered, LASzip 3)",
                laz::laszip_vlr_payload(laz_vlr));
    ++vlr_count;
  }

  constexpr std::size_t kHeader = 375;
  std::string h(kHeader, '\0');
  std::memcpy(h.data(), "LASF", 4);
  put<std::uint16_t>(h, 6, 0x10);  // formats 6-10 announce WKT CRS records
  h[24] = 1;
  h[25] = 4;
  std::memcpy(h.data() + 26, "ramus", 5);
  std::memcpy(h.data() + 58, "ramus", 5);
  put<std::uint16_t>(h, 94, kHeader);
  put<std::uint32_t>(h, 96, std::uint32_t(kHeader + vlrs.size()));
  put<std::uint32_t>(h, 100, vlr_count);
  h[104] = char(format | (o.compressed ? 0x80 : 0));
  put<std::uint16_t>(h, 105, std::uint16_t(record));
  // The legacy 32-bit counts stay 0: they exist only for formats 0-5.
  for (int k = 0; k < 3; ++k) {
    put<double>(h, 131 + 8 * k, scale);
    put<double>(h, 155 + 8 * k, cloud.offset[k]);
    put<double>(h, 179 + 16 * k, n ? hi[k] * scale + cloud.offset[k] : 0.0);
    put<double>(h, 187 + 16 * k, n ? lo[k] * scale + cloud.offset[k] : 0.0);
  }
  put<std::uint64_t>(h, 247, n);
  put<std::uint64_t>(h, 255, n);  // all first returns

  std::string out = h + vlrs;
  if (o.compressed) {
    out += laz::compress_points(laz_vlr, reinterpret_cast<const std::uint8_t*>(points.data()), n,
                                out.size());
  } else {
    out += points;
  }
  return out;
}

void write_point_cloud_las(const std::string& path, const PointCloud& cloud,
                           LasWriteOptions options) {
  options.compressed =
      formats_detail::lowercase(path.substr(path.size() >= 4 ? path.size() - 4 : 0)) == ".laz";
  write_file_atomically(path, point_cloud_to_las(cloud, options));
}

}  // namespace ramus
