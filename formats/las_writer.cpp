#include "formats/las_writer.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include "core/little_endian.h"

namespace ramus {
namespace {

constexpr double kScale = 0.001;  // 1 mm: below any scanner's range noise
constexpr std::uint16_t kHeaderSize = 227;
constexpr std::uint16_t kRecordSize = 20;

void put_text(std::string& out, const char* text, std::size_t width) {
  std::string field(text);
  field.resize(width, '\0');
  out += field;
}

std::int32_t grid(double world, double offset) {
  const double q = std::round((world - offset) / kScale);
  if (!(q >= double(std::numeric_limits<std::int32_t>::min()) &&
        q <= double(std::numeric_limits<std::int32_t>::max()))) {
    throw WriteError("a point lies too far from the cloud's centre for a LAS file at 1 mm");
  }
  return std::int32_t(q);
}

}  // namespace

std::string point_cloud_to_las(const PointCloud& c) {
  const std::size_t n = c.size();
  if ((!c.intensity.empty() && c.intensity.size() != n) ||
      (!c.classification.empty() && c.classification.size() != n)) {
    throw WriteError("point cloud '" + c.source +
                     "' has a channel whose length differs from the point count");
  }
  if (n > 0xffffffffull) throw WriteError("LAS 1.2 holds at most 4,294,967,295 points");
  // The offset on whole metres (the cloud's own is already rounded by every reader), so the
  // integer grid is the same for every file of a plot.
  const Vec3 offset{std::round(c.offset.x), std::round(c.offset.y), std::round(c.offset.z)};
  // Bounds of the stored (grid) coordinates first: the header precedes the records.
  Vec3 lo{0, 0, 0}, hi{0, 0, 0};
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 w = c.world(i);
    for (int k = 0; k < 3; ++k) {
      const double stored = offset[k] + grid(w[k], offset[k]) * kScale;
      lo[k] = i == 0 ? stored : std::min(lo[k], stored);
      hi[k] = i == 0 ? stored : std::max(hi[k], stored);
    }
  }
  std::string out;
  out.reserve(kHeaderSize + n * kRecordSize);
  out += "LASF";
  append_little_endian(out, std::uint16_t(0));  // file source id
  append_little_endian(out, std::uint16_t(0));  // global encoding: GPS week time
  out.append(16, '\0');                         // project GUID
  append_little_endian(out, std::uint8_t(1));
  append_little_endian(out, std::uint8_t(2));
  put_text(out, "ramus", 32);  // system identifier
  put_text(out, "ramus", 32);  // generating software
  // Creation day and year left 0 (allowed), so the same cloud always gives the same bytes.
  append_little_endian(out, std::uint16_t(0));
  append_little_endian(out, std::uint16_t(0));
  append_little_endian(out, kHeaderSize);
  append_little_endian(out, std::uint32_t(kHeaderSize));  // offset to point data
  append_little_endian(out, std::uint32_t(0));            // variable-length records
  append_little_endian(out, std::uint8_t(0));             // point data format 0
  append_little_endian(out, kRecordSize);
  append_little_endian(out, std::uint32_t(n));
  append_little_endian(out, std::uint32_t(n));  // points by return: all first returns
  for (int r = 1; r < 5; ++r) append_little_endian(out, std::uint32_t(0));
  for (int k = 0; k < 3; ++k) append_little_endian(out, kScale);
  for (int k = 0; k < 3; ++k) append_little_endian(out, offset[k]);
  for (int k = 0; k < 3; ++k) {
    append_little_endian(out, hi[k]);
    append_little_endian(out, lo[k]);
  }
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 w = c.world(i);
    for (int k = 0; k < 3; ++k) append_little_endian(out, grid(w[k], offset[k]));
    const float intensity = c.intensity.empty() ? 0.0f : c.intensity[i];
    append_little_endian(out, std::uint16_t(std::clamp(std::lround(intensity), 0L, 65535L)));
    append_little_endian(out, std::uint8_t(0x09));  // return 1 of 1
    append_little_endian(out, std::uint8_t(c.classification.empty() ? 0 : c.classification[i]));
    append_little_endian(out, std::int8_t(0));    // scan angle rank
    append_little_endian(out, std::uint8_t(0));   // user data
    append_little_endian(out, std::uint16_t(0));  // point source id
  }
  return out;
}

void write_point_cloud_las(const std::string& path, const PointCloud& cloud) {
  write_file_atomically(path, point_cloud_to_las(cloud));
}

}  // namespace ramus
