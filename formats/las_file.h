// LAS/LAZ files beyond reading them into a PointCloud (point_cloud_io.h does that, LAZ
// included): decompressing a LAZ file into the plain LAS file of the same records, and writing
// clouds as LAS 1.4.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "formats/point_cloud_io.h"

namespace ramus {

// The uncompressed LAS file of a LAZ file's bytes: the same header and VLRs without the
// "laszip encoded" VLR (the point data offset and VLR count adjusted, the point format byte's
// compression bits cleared), then the decoded records. EVLRs after the points are not kept.
// A LAS file that is not compressed is a FormatError saying so; malformed LAZ as in read_las.
std::string decompress_laz(std::string_view bytes, const std::string& name);

// The LAZ file of an uncompressed LAS file's bytes (the inverse of decompress_laz): a laszip VLR
// is added after the others and the records are compressed in chunks of `chunk_size` points.
// Point formats 0-3 (LASzip 2 items) and 6-8 (the layered coder), with any extra bytes; formats
// 4-5 and 9-10 (wave packets) are a FormatError.
std::string compress_las(std::string_view bytes, const std::string& name,
                         std::uint32_t chunk_size = 50000);

// A per-point attribute written as LAS 1.4 "extra bytes" (described in an Extra Bytes VLR, so
// PDAL, lidR, CloudCompare and laspy show it by name): either u8 or f32 values, one per point.
struct LasExtraBytes {
  std::string name;         // at most 32 characters
  std::string description;  // at most 32 characters
  std::vector<std::uint8_t> u8;
  std::vector<float> f32;
};

struct LasWriteOptions {
  // LAZ (the same point format 6 records compressed by the layered coder) instead of LAS.
  // write_point_cloud_las sets it from the file's extension.
  bool compressed = false;
  // Coordinate resolution in metres; 0 picks 0.1 mm, coarser only when the cloud's extent would
  // not fit 32-bit integers. The offset is the cloud's own (whole units), both in double.
  double scale = 0;
  std::vector<LasExtraBytes> extra;
};

// A LAS 1.4 file (point format 6) of `cloud`: world coordinates at the chosen scale, intensity
// and classification when the cloud has them (0 otherwise), every point
// return 1 of 1, the header's bounds and counts from the points. Deterministic: no dates.
std::string point_cloud_to_las(const PointCloud& cloud, const LasWriteOptions& options = {});

// Writes point_cloud_to_las to `path` atomically; a path ending in .laz is written compressed.
void write_point_cloud_las(const std::string& path, const PointCloud& cloud,
                           LasWriteOptions options = {});

}  // namespace ramus
