// LAS/LAZ files beyond reading them into a PointCloud (point_cloud_io.h does that, LAZ
// included): decompressing a LAZ file into the plain LAS file of the same records, and writing
// clouds as LAS 1.4.
#pragma once

#include <string>
#include <string_view>

#include "formats/point_cloud_io.h"

namespace ramus {

// The uncompressed LAS file of a LAZ file's bytes: the same header and VLRs without the
// "laszip encoded" VLR (the point data offset and VLR count adjusted, the point format byte's
// compression bits cleared), then the decoded records. EVLRs after the points are not kept.
// A LAS file that is not compressed is a FormatError saying so; malformed LAZ as in read_las.
std::string decompress_laz(std::string_view bytes, const std::string& name);

}  // namespace ramus
