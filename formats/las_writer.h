// A minimal LAS writer: LAS 1.2, point data format 0 (x, y, z as 32-bit integers at a 1 mm
// scale about a whole-metre offset, intensity, classification; one return per pulse), no
// variable-length records. Enough for simulated plots (`ramus scan --forest`) and tiles
// (`ramus tile`), which every LAS reader (ours, PDAL, lidR, CloudCompare) reads; LAS 1.4 and LAZ
// writing with the full point formats belong to the LAS/LAZ codec (issue 21, point 1).
#pragma once

#include <string>

#include "core/atomic_file.h"  // WriteError
#include "core/point_cloud.h"

namespace ramus {

// The file's bytes. Throws WriteError when a coordinate does not fit the 1 mm integer grid
// (more than 2,000 km from the cloud's offset), a channel's length differs from the point count
// or there are more than 2^32 - 1 points.
std::string point_cloud_to_las(const PointCloud& cloud);

// Writes point_cloud_to_las through write_file_atomically.
void write_point_cloud_las(const std::string& path, const PointCloud& cloud);

}  // namespace ramus
