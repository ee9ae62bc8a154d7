// Helpers shared by the point-cloud readers: errors with positions, text lines and tokens,
// numbers via std::from_chars (no iostreams per number), endian-aware loads from raw bytes, and
// the CloudBuilder that collects points in double precision and recentres them at the end.
#pragma once

#include <cstdint>
#include <cstring>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/point_cloud.h"
#include "formats/point_cloud_io.h"

namespace ramus::formats_detail {

[[noreturn]] void fail_at_line(const std::string& file, std::size_t line, std::string message);
[[noreturn]] void fail_at_byte(const std::string& file, std::size_t byte, std::string message);
[[noreturn]] void fail(const std::string& file, std::string message);

// `token` in single quotes for a message: at most 40 characters, non-printable bytes as \xNN.
std::string quoted(std::string_view token);

// Case-insensitive ASCII equality and lower-casing.
bool iequals(std::string_view a, std::string_view b);
std::string lowercase(std::string_view s);

// Parses the whole of `token` as a number (a leading '+' is allowed; "nan" and "inf" parse).
bool parse_double(std::string_view token, double& out);
// Parses the whole of `token` as a non-negative integer that fits in 64 bits.
bool parse_u64(std::string_view token, std::uint64_t& out);

// Walks `text` line by line; lines exclude the '\n' and a trailing '\r'. Line numbers are 1-based.
class LineCursor {
 public:
  explicit LineCursor(std::string_view text) : text_(text) {}
  bool next(std::string_view& line);
  std::size_t line_number() const { return line_; }  // of the line last returned
  std::size_t offset() const { return pos_; }        // byte just after the line last returned

 private:
  std::string_view text_;
  std::size_t pos_ = 0;
  std::size_t line_ = 0;
};

// Splits `line` at runs of spaces/tabs and of any character in `extra_separators`.
void split_tokens(std::string_view line, std::string_view extra_separators,
                  std::vector<std::string_view>& tokens);

std::string_view trim(std::string_view s);

// Loads a value of type T from `p` (unaligned), stored little or big endian.
template <typename T>
T load(const char* p, bool big_endian) {
  unsigned char b[sizeof(T)];
  std::memcpy(b, p, sizeof(T));
  if (big_endian) {
    for (std::size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(b[i], b[sizeof(T) - 1 - i]);
  }
  T v;
  std::memcpy(&v, b, sizeof(T));
  return v;
}
template <typename T>
T load_le(const char* p) {
  return load<T>(p, false);
}

// double -> float that is defined for every input: out-of-range values saturate to +-infinity
// (what IEEE hardware does, but C++ leaves undefined), NaN stays NaN.
float to_float(double d);

// One pass of a reader over a file (formats/point_cloud_io.cpp drives the passes).
struct ReadPass {
  // With ReadOptions::thin: the cloud's offset, known from a pass before; unset on the first
  // pass, where the reader may give the builder a guess (guess_offset).
  std::optional<Vec3> offset;
  VoxelThinner* thinner = nullptr;  // set exactly when the read thins
  // The reader is done with the file's bytes before this offset (a mapped file drops them).
  std::function<void(std::size_t)> release;
};

// Thrown by CloudBuilder::finish when a thinned pass assumed another offset than the cloud's:
// the read is repeated with `offset` (formats/point_cloud_io.cpp).
struct OffsetRetry {
  Vec3 offset;
};

// Collects points and turns them into a recentred PointCloud. Unthinned, it keeps every point in
// double precision until the offset (the centre of their bounding box) is known. Thinned, it
// narrows each point against an assumed offset at once, keeps the points the thinner keeps and
// only the bounding box of the others; finish() then checks the assumption (OffsetRetry).
class CloudBuilder {
 public:
  CloudBuilder(std::string name, const ReadOptions& options, const ReadPass& pass);

  void enable_normals() { has_normals_ = true; }
  void enable_intensity() { has_intensity_ = true; }
  void enable_classification() { has_classification_ = true; }
  void set_scanner(const Vec3& origin) {
    scanner_ = origin;
    has_scanner_ = true;
  }
  // Reserves room for `n` points but never more than `cap` (so a lying header cannot make us
  // allocate gigabytes before the data proves it exists).
  void reserve(std::uint64_t n, std::uint64_t cap);

  // Adds a point; channels that were not enabled are ignored. Returns false when the point was
  // dropped for a non-finite coordinate; the caller then raises its positioned error if
  // strict() (ReadOptions::skip_non_finite is false).
  bool add(const Vec3& p, const Vec3& normal = {}, double intensity = 0, std::uint8_t cls = 0);
  bool strict() const { return !options_.skip_non_finite; }
  std::size_t count() const { return added_; }  // finite points added, kept or not

  // A thinned first pass assumes this offset (e.g. from a LAS header's box); call before add.
  // Without a guess the first pass only measures the bounding box.
  void guess_offset(const Vec3& lo, const Vec3& hi);
  // The reader is done with the bytes before `byte` (see ReadPass::release).
  void release(std::size_t byte) const {
    if (pass_.release) pass_.release(byte);
  }
  // Whether any point added (kept or not) had a non-zero intensity or class.
  bool any_intensity() const { return any_intensity_; }
  bool any_classification() const { return any_classification_; }

  // Recentres and narrows; throws FormatError when no point was read.
  PointCloud finish(ReadReport* report, Format format, std::string variant);

 private:
  std::string name_;
  ReadOptions options_;
  const ReadPass& pass_;
  std::uint64_t max_points_;  // core/input_file.h, --max-points
  std::optional<Vec3> assumed_;  // thinned: the offset the kept points are narrowed against
  std::vector<Vec3> points_;     // unthinned
  std::vector<Vec3f> kept_;      // thinned: relative to *assumed_
  Vec3 lo_, hi_;                 // bounding box of every finite point added
  std::size_t added_ = 0;
  bool any_intensity_ = false, any_classification_ = false;
  std::vector<Vec3f> normals_;
  std::vector<float> intensity_;
  std::vector<std::uint8_t> classification_;
  bool has_normals_ = false, has_intensity_ = false, has_classification_ = false;
  bool has_scanner_ = false;
  Vec3 scanner_;
  std::size_t skipped_ = 0;
};

// The readers, one per file (read_<format>.cpp).
PointCloud read_ply(std::string_view bytes, const std::string& name, const ReadOptions& options,
                    const ReadPass& pass, ReadReport* report);
PointCloud read_xyz(std::string_view bytes, const std::string& name, const ReadOptions& options,
                    const ReadPass& pass, ReadReport* report);
PointCloud read_las(std::string_view bytes, const std::string& name, const ReadOptions& options,
                    const ReadPass& pass, ReadReport* report);
PointCloud read_pcd(std::string_view bytes, const std::string& name, const ReadOptions& options,
                    const ReadPass& pass, ReadReport* report);

// Where the parts of a LAS/LAZ file are, after the header and VLR checks of read_las.
struct LasLayout {
  unsigned minor = 0;
  std::size_t header_size = 0, point_offset = 0, vlr_end = 0;  // vlr_end: after the last VLR
  std::uint32_t vlr_count = 0;
  unsigned format = 0;  // compression bits cleared
  std::size_t record_length = 0;
  std::uint64_t count = 0;
  std::size_t laszip_vlr = 0, laszip_vlr_length = 0;  // payload offset (0: none) and length
};
LasLayout read_las_layout(std::string_view bytes, const std::string& name);

}  // namespace ramus::formats_detail
