// ramus inspect SCAN [--timing]
// Reads a point cloud (PLY, XYZ/TXT/ASC/CSV, LAS, PCD) and prints what a reconstruction would
// start from: the format, point count, world bounds, the recentring offset, the channels present
// and the scanner origin. Exit 0 on success, 1 when the file cannot be read (with the reader's
// positioned message).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <limits>
#include <memory>
#include <string>

#include "cli/command.h"
#include "formats/point_cloud_io.h"

namespace ramus::cli {

namespace {

struct InspectArgs {
  std::string scan;
  bool timing = false;
};

std::string channels(const PointCloud& c) {
  std::string s = "positions";
  if (!c.normals.empty()) s += ", normals";
  if (!c.intensity.empty()) s += ", intensity";
  if (!c.classification.empty()) s += ", classification";
  return s;
}

// Thousands separators make point counts readable at a glance.
std::string grouped(std::size_t n) {
  std::string digits = std::to_string(n), out;
  for (std::size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0) out += ',';
    out += digits[i];
  }
  return out;
}

void print_cloud(const InspectArgs& args, const PointCloud& c, const ReadReport& r) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  Vec3 lo{inf, inf, inf}, hi{-inf, -inf, -inf};
  for (const Vec3f& p : c.positions) {
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], double(p[k]));
      hi[k] = std::max(hi[k], double(p[k]));
    }
  }
  const Vec3 wlo = c.offset + lo, whi = c.offset + hi, ext = hi - lo;
  std::printf("file:     %s\n", args.scan.c_str());
  std::printf("format:   %s (%s)\n", format_name(r.format), r.variant.c_str());
  std::printf("points:   %s", grouped(c.size()).c_str());
  if (r.skipped > 0) {
    std::printf(" (%s skipped: non-finite coordinates)", grouped(r.skipped).c_str());
  }
  std::printf("\nbounds:   min %.3f %.3f %.3f\n          max %.3f %.3f %.3f\n", wlo.x, wlo.y, wlo.z,
              whi.x, whi.y, whi.z);
  std::printf("extent:   %.3f x %.3f x %.3f\n", ext.x, ext.y, ext.z);
  std::printf("offset:   %.17g %.17g %.17g\n", c.offset.x, c.offset.y, c.offset.z);
  std::printf("channels: %s\n", channels(c).c_str());
  if (c.scanner) {
    std::printf("scanner:  %.3f %.3f %.3f\n", c.scanner->x, c.scanner->y, c.scanner->z);
  } else {
    std::printf("scanner:  not given\n");
  }
}

int run_inspect(const InspectArgs& args) {
  ReadReport report;
  PointCloud cloud;
  auto t0 = std::chrono::steady_clock::now();
  try {
    cloud = read_point_cloud(args.scan, {}, &report);
  } catch (const FormatError& e) {
    throw UserError(e.what());
  }
  double ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  print_cloud(args, cloud, report);
  if (args.timing) std::printf("read in:  %.1f ms\n", ms);
  return 0;
}

}  // namespace

void add_inspect(CLI::App& app, const GlobalOptions&, std::function<int()>& run) {
  auto args = std::make_shared<InspectArgs>();
  CLI::App* sub = app.add_subcommand(
      "inspect", "read a scan (.ply .xyz .txt .asc .csv .las .laz .pcd) and print what it holds");
  sub->add_option("SCAN", args->scan, "the point-cloud file")->required();
  sub->add_flag("--timing", args->timing, "also print how long reading took");
  sub->callback([args, &run] { run = [args] { return run_inspect(*args); }; });
}

}  // namespace ramus::cli
