// LAZ <-> LAS of the same records (las_file.h): the header and VLRs are kept, the laszip VLR
// removed or added, and the records decoded or encoded by formats/laz/.
#include <algorithm>
#include <cstring>

#include "formats/detail/reader_util.h"
#include "formats/las_file.h"
#include "formats/laz/laz_points.h"
#include "formats/laz/laz_writer.h"

namespace ramus {

using namespace formats_detail;

namespace {

enum : std::size_t { kPointOffset = 96, kVlrCount = 100, kFormat = 104, kFirstEvlr = 235 };

template <typename T>
void poke(std::string& s, std::size_t at, T v) {
  std::memcpy(s.data() + at, &v, sizeof v);
}

// EVLRs after the points are not carried over: a LAS 1.4 header then must not point to any.
void drop_evlrs(std::string& out, const LasLayout& l) {
  if (l.minor < 4) return;
  poke<std::uint64_t>(out, kFirstEvlr, 0);
  poke<std::uint32_t>(out, kFirstEvlr + 8, 0);
}

}  // namespace

std::string decompress_laz(std::string_view bytes, const std::string& name) {
  const LasLayout l = read_las_layout(bytes, name);
  if (l.laszip_vlr == 0) fail(name, "the file is not LAZ-compressed (no 'laszip encoded' VLR)");
  const std::size_t vlr_start = l.laszip_vlr - 54;
  std::string out;
  out.reserve(l.point_offset +
              std::size_t(std::min<std::uint64_t>(l.count, bytes.size() * 4)) * l.record_length);
  out.append(bytes.substr(0, vlr_start));
  out.append(bytes.substr(l.laszip_vlr + l.laszip_vlr_length,
                          l.point_offset - l.laszip_vlr - l.laszip_vlr_length));
  poke<std::uint32_t>(out, kPointOffset, std::uint32_t(out.size()));
  poke<std::uint32_t>(out, kVlrCount, l.vlr_count - 1);
  out[kFormat] = char(l.format);
  drop_evlrs(out, l);
  laz::LazInput in{bytes,          name,    l.laszip_vlr, l.laszip_vlr_length,
                   l.point_offset, l.count, l.format,     l.record_length};
  laz::decode_laz_points(in, [&](const std::uint8_t* recs, std::size_t n, std::uint64_t) {
    out.append(reinterpret_cast<const char*>(recs), n * l.record_length);
  });
  return out;
}

std::string compress_las(std::string_view bytes, const std::string& name,
                         std::uint32_t chunk_size) {
  const LasLayout l = read_las_layout(bytes, name);
  if (l.laszip_vlr != 0) fail(name, "the file is LAZ-compressed already");
  laz::LaszipVlr vlr;
  if (chunk_size == 0 || !laz::v2_items(l.format, l.record_length, vlr, chunk_size)) {
    fail_at_byte(name, kFormat,
                 "point format " + std::to_string(l.format) + " with " +
                     std::to_string(l.record_length) +
                     "-byte records is not compressed by ramus (it writes formats 0-3 and "
                     "6-8)");
  }
  const std::size_t have = (bytes.size() - l.point_offset) / l.record_length;
  if (l.count > have) {
    fail_at_byte(name, bytes.size(),
                 "the header announces " + std::to_string(l.count) + " points but the file holds " +
                     std::to_string(have));
  }
  // Header and VLRs, the laszip VLR, then whatever lay between the VLRs and the points.
  const std::string payload = laz::laszip_vlr_payload(vlr);
  std::string out(bytes.substr(0, l.vlr_end));
  out.append(2, '\0');
  out.append("laszip encoded\0\0", 16);
  const std::uint16_t id = 22204, length = std::uint16_t(payload.size());
  out.append(reinterpret_cast<const char*>(&id), 2);
  out.append(reinterpret_cast<const char*>(&length), 2);
  std::string description = "by ramus (LASzip 2 items)";
  description.resize(32, '\0');
  out += description + payload;
  out.append(bytes.substr(l.vlr_end, l.point_offset - l.vlr_end));
  const std::uint32_t offset = std::uint32_t(out.size());
  poke<std::uint32_t>(out, kPointOffset, offset);
  poke<std::uint32_t>(out, kVlrCount, l.vlr_count + 1);
  out[kFormat] = char(l.format | 0x80);
  drop_evlrs(out, l);
  out += laz::compress_points(vlr,
                              reinterpret_cast<const std::uint8_t*>(bytes.data() + l.point_offset),
                              std::size_t(l.count), offset);
  return out;
}

}  // namespace ramus
