// Reading and writing point clouds (laser scans): PLY, XYZ/TXT/ASC/CSV, LAS 1.0-1.4, LAZ and PCD.
//
// Every reader produces a ramus::PointCloud whose positions are single precision relative to a
// double-precision `offset` chosen at the centre of the cloud's bounding box (computed from the
// points, never from a header) and rounded to a whole unit, so UTM-scale coordinates keep
// millimetre resolution. Malformed input never crashes: it raises FormatError naming the file and
// the line (text formats) or byte offset (binary formats) with what was expected there.
// The formats and their rules are described in docs/formats.md.
#pragma once

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>

#include "core/atomic_file.h"  // WriteError, thrown by the writers
#include "core/point_cloud.h"

namespace ramus {

class VoxelThinner;  // formats/voxel_thin.h

enum class Format { kAuto, kPly, kXyz, kLas, kPcd };

// "ply", "xyz", "las", "pcd" ("auto" for kAuto).
const char* format_name(Format f);

// The format a file name's extension suggests (.ply, .xyz/.txt/.asc/.csv/.pts, .las/.laz, .pcd),
// case-insensitive; kAuto when the extension says nothing.
Format format_from_extension(std::string_view path);

// The format the first bytes announce ("ply" line, "LASF" signature, a PCD header); kAuto when
// they announce none of these (plain text is then read as XYZ).
Format sniff_format(std::string_view bytes);

// A reader's complaint about its input. what() is "<file>: line N: <message>",
// "<file>: line N, column C: <message>" or "<file>: byte N: <message>" (or "<file>: <message>"
// when no position applies).
class FormatError : public std::runtime_error {
 public:
  static constexpr std::size_t kNoPosition = std::size_t(-1);
  FormatError(std::string file, std::size_t line, std::size_t byte, std::string message,
              std::size_t column = kNoPosition);

  const std::string& file() const { return file_; }
  std::size_t line() const { return line_; }      // 1-based; kNoPosition when not a text position
  std::size_t column() const { return column_; }  // 1-based; kNoPosition when not given
  std::size_t byte() const { return byte_; }      // 0-based; kNoPosition when not a byte position
  const std::string& message() const { return message_; }

 private:
  std::string file_;
  std::size_t line_;
  std::size_t byte_;
  std::string message_;
  std::size_t column_;
};

struct ReadOptions {
  // Points with a NaN or infinite coordinate are dropped and counted in ReadReport::skipped
  // (organized PCD clouds and some exporters mark missing returns that way). When false, the
  // first such point is a FormatError instead.
  bool skip_non_finite = true;
  // Voxel thinning while reading (formats/voxel_thin.h): when > 0, only the first point of each
  // cube of this edge is kept, and the reader holds only the kept points, not the file's. The
  // result is byte for byte thin_cloud(read without thinning, thin): the cube of a point is
  // decided on its position relative to the cloud's offset, which comes from the bounding box
  // of all points, so the reader thins against a guess of the offset (LAS/LAZ: the header's
  // box) and reads the file a second time when the guess proves wrong (text formats: always
  // a first pass for the box).
  double thin = 0;
  // With thin > 0: a thinner shared by several files (`ramus tile` thins across its scans);
  // null: one of the read's own. Its size() is used, not `thin`.
  VoxelThinner* thinner = nullptr;
};

// What a reader found besides the points, for `ramus inspect` and for callers that want to warn.
struct ReadReport {
  Format format = Format::kAuto;
  std::string variant;                     // e.g. "binary_little_endian", "LAS 1.4 point format 6"
  std::size_t points_read = 0;             // points kept in the cloud
  std::size_t skipped = 0;                 // points dropped for non-finite coordinates
  std::size_t points_before_thinning = 0;  // finite points in the file (= points_read unthinned)
  int passes = 0;                          // times the file was read (2: a thinned read's retry)
};

// Reads the file at `path`. The format comes from the content's magic bytes when they announce
// one, else from the extension, else plain text is read as XYZ. An empty file or one without
// points is a FormatError. LAZ (compressed LAS) is decompressed chunk by chunk (formats/laz/).
// The file is memory-mapped and the LAS, LAZ and XYZ readers hand back the pages they are done
// with as they go, so with ReadOptions::thin the resident memory is the thinned cloud plus a
// window of the file (docs/scale.md, "Bounded memory").
PointCloud read_point_cloud(const std::string& path, const ReadOptions& options = {},
                            ReadReport* report = nullptr);

// Reads a cloud held in memory; `name` is used in messages and stored as PointCloud::source.
// With Format::kAuto the format is sniffed from the bytes, then from `name`'s extension.
PointCloud read_point_cloud_bytes(std::string_view bytes, Format format, const std::string& name,
                                  const ReadOptions& options = {}, ReadReport* report = nullptr);

// Writes `cloud` as PLY (binary little endian, or ascii when binary is false). Positions are
// written as float relative to nothing when the cloud's offset is zero; otherwise as double world
// coordinates (offset + position), so no precision is lost. Normals, intensity and
// classification are written when present. Goes through write_file_atomically.
void write_point_cloud_ply(const std::string& path, const PointCloud& cloud, bool binary = true);

// Writes `cloud` as text: a "# x y z [nx ny nz] [intensity] [classification]" header comment,
// then one point per line in world coordinates (shortest round-trip decimal form).
void write_point_cloud_xyz(const std::string& path, const PointCloud& cloud);

// The same writers into memory (what the file versions write).
std::string point_cloud_to_ply(const PointCloud& cloud, bool binary = true);
std::string point_cloud_to_xyz(const PointCloud& cloud);

}  // namespace ramus
