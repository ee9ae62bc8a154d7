#include "cli/scan_args.h"

#include <cstdio>
#include <sstream>

#include "cli/command.h"
#include "formats/point_cloud_io.h"

namespace ramus::cli {

Vec3 parse_scanner(const std::string& text) {
  std::istringstream in(text);
  Vec3 v;
  char c1 = 0, c2 = 0;
  if (!(in >> v.x >> c1 >> v.y >> c2 >> v.z) || c1 != ',' || c2 != ',' || !(in >> std::ws).eof() ||
      !is_finite(v)) {
    throw UserError("--scanner expects three numbers x,y,z, not '" + text + "'");
  }
  return v;
}

AlignedScan read_aligned_scan(const std::string& path, const std::string& scanner,
                              const char* command, bool quiet) {
  wavelet::AlignOptions ao;
  if (!scanner.empty()) ao.scanner = parse_scanner(scanner);
  AlignedScan scan;
  try {
    scan.cloud = read_point_cloud(path);
  } catch (const FormatError& e) {
    throw UserError(e.what());
  }
  scan.aligned = wavelet::align_cloud(scan.cloud, ao);
  if (!scan.aligned.alignment.warning.empty() && !quiet) {
    std::fprintf(stderr, "ramus %s: warning: %s\n", command,
                 scan.aligned.alignment.warning.c_str());
  }
  return scan;
}

std::string file_name(const std::string& path) {
  std::size_t slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

}  // namespace ramus::cli
