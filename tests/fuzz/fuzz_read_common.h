// The body of the point-cloud reader fuzz targets (fuzz_read_<format>.cpp): any input either
// reads or raises FormatError, with and without skipping non-finite points; a cloud that reads
// must survive a PLY write and read-back with the same point count.
#pragma once

#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "formats/point_cloud_io.h"

namespace ramus::fuzz {

// `name` is the file name errors would mention ("fuzz.las", ...).
inline int read_point_cloud_once(const std::uint8_t* data, std::size_t size, Format format,
                                 const char* name) {
  std::string_view bytes(reinterpret_cast<const char*>(data), size);
  for (bool skip : {true, false}) {
    ReadOptions options;
    options.skip_non_finite = skip;
    try {
      PointCloud cloud = read_point_cloud_bytes(bytes, format, name, options);
      PointCloud again =
          read_point_cloud_bytes(point_cloud_to_ply(cloud), Format::kPly, "again.ply");
      if (again.size() != cloud.size()) std::abort();
    } catch (const FormatError&) {
    }
  }
  return 0;
}

}  // namespace ramus::fuzz
