// LAS reader: ASPRS LAS 1.0-1.4, point data record formats 0-10, uncompressed.
// Field offsets follow the public header block tables of the LAS 1.4 specification (R13): the
// 1.0-1.2 header is 227 bytes, 1.3 adds the waveform start (235), 1.4 the EVLR fields and the
// 64-bit point counts (375). Coordinates are X * scale + offset in double precision. The header's
// bounding box is never used (writers leave it zeroed or stale): bounds come from the points.
// Records may be longer than their format's minimum (extra bytes), which are skipped.
// LAZ (point format byte with bit 7 or 6 set, and a "laszip encoded" VLR) is decompressed chunk
// by chunk by formats/laz/ and its records go through the same conversion.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "formats/detail/reader_util.h"
#include "formats/laz/laz_points.h"

namespace ramus::formats_detail {
namespace {

// Minimum record size of point data record formats 0-10 (LAS 1.4 tables 7-21).
constexpr std::size_t kRecordSize[] = {20, 28, 26, 34, 57, 63, 30, 36, 38, 59, 67};

// Byte offsets of public header fields.
enum : std::size_t {
  kVersionMajor = 24,
  kVersionMinor = 25,
  kHeaderSize = 94,
  kPointOffset = 96,
  kVlrCount = 100,
  kFormat = 104,
  kRecordLength = 105,
  kLegacyCount = 107,
  kScale = 131,
  kOffset = 155,
  kMaxX = 179,  // then min x, max y, min y, max z, min z
  kCount64 = 247,
};

struct LasHeader {
  unsigned major = 0, minor = 0;
  std::size_t header_size = 0;
  std::size_t point_offset = 0;
  std::uint32_t vlr_count = 0;
  unsigned format = 0;
  std::size_t record_length = 0;
  std::uint64_t count = 0;
  double scale[3] = {1, 1, 1};
  double offset[3] = {0, 0, 0};
  Vec3 box_lo, box_hi;           // the header's bounding box: only a guess (see read_las)
  bool compressed_bits = false;  // the point format byte's bit 7 or 6 (LAZ)
  std::size_t laszip_vlr = 0;    // payload offset of the "laszip encoded" VLR (0: none)
  std::size_t laszip_vlr_length = 0;
};

std::size_t min_header_size(unsigned minor) { return minor >= 4 ? 375 : minor == 3 ? 235 : 227; }

void parse_fixed_fields(std::string_view b, const std::string& file, LasHeader& h) {
  const char* d = b.data();
  h.major = std::uint8_t(d[kVersionMajor]);
  h.minor = std::uint8_t(d[kVersionMinor]);
  if (h.major != 1 || h.minor > 4) {
    fail_at_byte(file, kVersionMajor,
                 "unsupported LAS version " + std::to_string(h.major) + "." +
                     std::to_string(h.minor) + " (expected 1.0 to 1.4)");
  }
  h.header_size = load_le<std::uint16_t>(d + kHeaderSize);
  if (h.header_size < min_header_size(h.minor)) {
    fail_at_byte(file, kHeaderSize,
                 "header size " + std::to_string(h.header_size) + " is smaller than the " +
                     std::to_string(min_header_size(h.minor)) + " bytes of a LAS 1." +
                     std::to_string(h.minor) + " header");
  }
  if (h.header_size > b.size()) {
    fail_at_byte(file, b.size(),
                 "the header is cut off: it is " + std::to_string(h.header_size) +
                     " bytes, the file ends first");
  }
  h.point_offset = load_le<std::uint32_t>(d + kPointOffset);
  if (h.point_offset < h.header_size || h.point_offset > b.size()) {
    fail_at_byte(file, kPointOffset,
                 "offset to point data " + std::to_string(h.point_offset) +
                     " is outside the file (header " + std::to_string(h.header_size) +
                     " bytes, file " + std::to_string(b.size()) + " bytes)");
  }
  h.vlr_count = load_le<std::uint32_t>(d + kVlrCount);
}

void parse_point_fields(std::string_view b, const std::string& file, LasHeader& h) {
  const char* d = b.data();
  const unsigned format_byte = std::uint8_t(d[kFormat]);
  h.compressed_bits = (format_byte & 0xc0) != 0;
  h.format = format_byte & 0x3f;
  if (h.format > 10) {
    fail_at_byte(
        file, kFormat,
        "unknown point data record format " + std::to_string(h.format) + " (expected 0 to 10)");
  }
  h.record_length = load_le<std::uint16_t>(d + kRecordLength);
  if (h.record_length < kRecordSize[h.format]) {
    fail_at_byte(file, kRecordLength,
                 "point data record length " + std::to_string(h.record_length) +
                     " is smaller than the " + std::to_string(kRecordSize[h.format]) +
                     " bytes of point format " + std::to_string(h.format));
  }
  h.count = load_le<std::uint32_t>(d + kLegacyCount);
  if (h.minor >= 4) {
    // LAS 1.4 keeps the 32-bit count only for old readers (0 for formats 6-10 or > 2^32 points).
    std::uint64_t count64 = load_le<std::uint64_t>(d + kCount64);
    if (count64 != 0) h.count = count64;
  }
  static const char* axis[] = {"x", "y", "z"};
  for (int k = 0; k < 3; ++k) {
    h.scale[k] = load_le<double>(d + kScale + 8 * k);
    h.offset[k] = load_le<double>(d + kOffset + 8 * k);
    if (!std::isfinite(h.scale[k]) || h.scale[k] == 0) {
      fail_at_byte(
          file, kScale + 8 * k,
          std::string(axis[k]) + " scale factor is " + (h.scale[k] == 0 ? "zero" : "not finite"));
    }
    if (!std::isfinite(h.offset[k])) {
      fail_at_byte(file, kOffset + 8 * k, std::string(axis[k]) + " offset is not finite");
    }
    h.box_hi[k] = load_le<double>(d + kMaxX + 16 * k);
    h.box_lo[k] = load_le<double>(d + kMaxX + 16 * k + 8);
  }
}

// Walks the variable length records between the header and the point data: each must fit; a
// laszip VLR means the points are compressed (even if the format byte does not say so).
void check_vlrs(std::string_view b, const std::string& file, LasHeader& h) {
  constexpr std::size_t kVlrHeader = 54;
  std::size_t pos = h.header_size;
  for (std::uint32_t i = 0; i < h.vlr_count; ++i) {
    if (h.point_offset - pos < kVlrHeader) {
      fail_at_byte(file, pos,
                   "variable length record " + std::to_string(i + 1) + " of " +
                       std::to_string(h.vlr_count) + " runs past the start of point data at byte " +
                       std::to_string(h.point_offset));
    }
    std::string_view user = b.substr(pos + 2, 16);
    user = user.substr(0, user.find('\0'));
    std::uint16_t record_id = load_le<std::uint16_t>(b.data() + pos + 18);
    std::size_t length = load_le<std::uint16_t>(b.data() + pos + 20);
    if (h.point_offset - pos - kVlrHeader < length) {
      fail_at_byte(file, pos + 20,
                   "variable length record " + std::to_string(i + 1) + " of " +
                       std::to_string(h.vlr_count) + " (" + quoted(user) +
                       ") runs past the start of point data at byte " +
                       std::to_string(h.point_offset));
    }
    if (user == "laszip encoded" && record_id == 22204) {
      h.laszip_vlr = pos + kVlrHeader;
      h.laszip_vlr_length = length;
    }
    pos += kVlrHeader + length;
  }
  if (h.compressed_bits && h.laszip_vlr == 0) {
    char hex[8];
    std::snprintf(hex, sizeof hex, "0x%02x", unsigned(std::uint8_t(b[kFormat])));
    fail_at_byte(file, kFormat,
                 std::string("point format byte ") + hex +
                     " marks the points LAZ-compressed but there is no 'laszip encoded' "
                     "variable length record (user id 'laszip encoded', record 22204)");
  }
}

// One point record to a point: coordinates at the header's scale and offset in double.
bool add_record(const char* rec, const LasHeader& h, CloudBuilder& builder) {
  Vec3 p;
  for (int k = 0; k < 3; ++k) {
    p[k] = double(load_le<std::int32_t>(rec + 4 * k)) * h.scale[k] + h.offset[k];
  }
  double intensity = load_le<std::uint16_t>(rec + 12);
  // Formats 0-5 keep the class in the low 5 bits of byte 15 (bits 5-7 are flags); formats
  // 6-10 give it the whole byte 16.
  std::uint8_t cls = h.format >= 6 ? std::uint8_t(rec[16]) : std::uint8_t(rec[15] & 0x1f);
  return builder.add(p, {}, intensity, cls);
}

void read_laz_points(std::string_view b, const std::string& file, const LasHeader& h,
                     CloudBuilder& builder) {
  builder.enable_intensity();
  builder.enable_classification();
  laz::LazInput in{b,       file,     h.laszip_vlr,   h.laszip_vlr_length, h.point_offset,
                   h.count, h.format, h.record_length};
  in.release = [&builder](std::size_t byte) { builder.release(byte); };
  // Bounded by what the file could plausibly hold; the builder grows past it if need be.
  builder.reserve(h.count, b.size() * 4);
  laz::decode_laz_points(in, [&](const std::uint8_t* recs, std::size_t n, std::uint64_t first) {
    const char* rec = reinterpret_cast<const char*>(recs);
    for (std::size_t i = 0; i < n; ++i, rec += h.record_length) {
      if (!add_record(rec, h, builder) && builder.strict()) {
        fail_at_byte(file, h.point_offset,
                     "point " + std::to_string(first + i) + " has a non-finite coordinate");
      }
    }
  });
}

void read_points(std::string_view b, const std::string& file, const LasHeader& h,
                 CloudBuilder& builder) {
  const std::size_t available = b.size() - h.point_offset;
  const std::size_t complete = available / h.record_length;
  if (h.count > complete) {
    fail_at_byte(file, h.point_offset + complete * h.record_length,
                 "the header announces " + std::to_string(h.count) + " points of " +
                     std::to_string(h.record_length) + " bytes but the file holds only " +
                     std::to_string(complete) + " complete records");
  }
  builder.enable_intensity();
  builder.enable_classification();
  builder.reserve(h.count, complete);
  const char* rec = b.data() + h.point_offset;
  for (std::uint64_t i = 0; i < h.count; ++i, rec += h.record_length) {
    if (!add_record(rec, h, builder) && builder.strict()) {
      fail_at_byte(file, std::size_t(rec - b.data()),
                   "point " + std::to_string(i) + " has a non-finite coordinate");
    }
    if ((i & 0xffff) == 0xffff) builder.release(std::size_t(rec - b.data()));
  }
}

}  // namespace

PointCloud read_las(std::string_view bytes, const std::string& name, const ReadOptions& options,
                    const ReadPass& pass, ReadReport* report) {
  if (bytes.substr(0, 4) != "LASF") {
    fail_at_byte(name, 0, "expected the LAS signature 'LASF', found " + quoted(bytes.substr(0, 4)));
  }
  if (bytes.size() < 227) {
    fail_at_byte(name, bytes.size(),
                 "the header is cut off: a LAS header has at least 227 "
                 "bytes, the file ends after " +
                     std::to_string(bytes.size()));
  }
  LasHeader h;
  parse_fixed_fields(bytes, name, h);
  parse_point_fields(bytes, name, h);
  check_vlrs(bytes, name, h);
  CloudBuilder builder(name, options, pass);
  // A thinned read narrows its points against the offset the header's box gives; when the box
  // is stale the offset proves different at the end and the file is read again.
  builder.guess_offset(h.box_lo, h.box_hi);
  const bool laz = h.laszip_vlr != 0;
  if (laz) {
    read_laz_points(bytes, name, h, builder);
  } else {
    read_points(bytes, name, h, builder);
  }
  std::string variant = std::string(laz ? "LAZ " : "LAS ") + std::to_string(h.major) + "." +
                        std::to_string(h.minor) + ", point format " + std::to_string(h.format) +
                        ", " + std::to_string(h.record_length) + "-byte records";
  if (h.record_length > kRecordSize[h.format]) {
    variant += " (" + std::to_string(h.record_length - kRecordSize[h.format]) + " extra bytes)";
  }
  if (laz) {
    variant += ", " + laz::describe_laz({bytes, name, h.laszip_vlr, h.laszip_vlr_length,
                                         h.point_offset, h.count, h.format, h.record_length});
  }
  PointCloud cloud = builder.finish(report, Format::kLas, variant);
  // Every record has intensity and class fields; all zeros (over every point read, thinned away
  // or not) means the scanner recorded none.
  if (!builder.any_intensity()) cloud.intensity.clear();
  if (!builder.any_classification()) cloud.classification.clear();
  return cloud;
}

LasLayout read_las_layout(std::string_view bytes, const std::string& name) {
  if (bytes.substr(0, 4) != "LASF") {
    fail_at_byte(name, 0, "expected the LAS signature 'LASF', found " + quoted(bytes.substr(0, 4)));
  }
  if (bytes.size() < 227) fail_at_byte(name, bytes.size(), "the header is cut off");
  LasHeader h;
  parse_fixed_fields(bytes, name, h);
  parse_point_fields(bytes, name, h);
  check_vlrs(bytes, name, h);
  LasLayout l;
  l.minor = h.minor;
  l.header_size = h.header_size;
  l.point_offset = h.point_offset;
  l.vlr_count = h.vlr_count;
  l.vlr_end = h.header_size;
  for (std::uint32_t i = 0; i < h.vlr_count; ++i) {
    l.vlr_end += 54 + load_le<std::uint16_t>(bytes.data() + l.vlr_end + 20);
  }
  l.format = h.format;
  l.record_length = h.record_length;
  l.count = h.count;
  l.laszip_vlr = h.laszip_vlr;
  l.laszip_vlr_length = h.laszip_vlr_length;
  return l;
}

}  // namespace ramus::formats_detail
