// Small helpers shared by the subcommands that read scans (compress, enhance).
#pragma once

#include <string>

#include "core/point_cloud.h"
#include "core/vec3.h"
#include "infer/wavelet/alignment.h"

namespace ramus::cli {

// "x,y,z" -> Vec3; throws UserError naming the text otherwise.
Vec3 parse_scanner(const std::string& text);

// A scan as read from its file and aligned (Friedman & Stamos 2013, III-A).
struct AlignedScan {
  PointCloud cloud;
  wavelet::AlignedCloud aligned;
};

// Reads the point cloud at `path` (a FormatError becomes a UserError) and aligns it, with the
// scanner at `scanner` ("x,y,z", see parse_scanner) unless it is empty. The alignment's warning
// goes to stderr as "ramus <command>: warning: ..." unless `quiet`.
AlignedScan read_aligned_scan(const std::string& path, const std::string& scanner,
                              const char* command, bool quiet);

// The last path component, for table rows.
std::string file_name(const std::string& path);

}  // namespace ramus::cli
