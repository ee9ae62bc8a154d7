// ramus symmetrize SCAN -o OUT.ply|.xyz [--scanner x,y,z] [--merge-distance D]
// The preprocessing step of Friedman & Stamos 2013, IV-D: a single-view scan merged with its
// reflection about the vertical plane through the root perpendicular to the scanner direction
// (after the alignment of III-A). The output aligns like the input only with the same scanner
// direction, so the command prints the --scanner value to pass to the next step.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>

#include "cli/command.h"
#include "cli/output_path.h"
#include "cli/scan_args.h"
#include "core/number_text.h"
#include "formats/point_cloud_io.h"
#include "infer/wavelet/symmetrize.h"

namespace ramus::cli {
namespace {

struct SymmetrizeArgs {
  std::string scan, output, scanner;
  double merge_distance = -1;
};

bool ends_with(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

// A scanner position that gives the same alignment as `a`: any point on the horizontal line
// through the root against the scanner direction does; the given one is reused when known.
Vec3 equivalent_scanner(const wavelet::Alignment& a, const std::optional<Vec3>& known,
                        double distance) {
  if (known && a.source != wavelet::ScannerSource::centroid) return *known;
  return a.root - a.scanner_dir * (distance > 0 ? distance : 1.0);
}

int run_symmetrize(const SymmetrizeArgs& a, const GlobalOptions& global) {
  if (!ends_with(a.output, ".ply") && !ends_with(a.output, ".xyz")) {
    throw UserError("-o: the output must end in .ply or .xyz, not '" + a.output + "'");
  }
  AlignedScan scan;
  try {
    scan = read_aligned_scan(a.scan, a.scanner, "symmetrize", global.quiet);
  } catch (const std::invalid_argument& e) {
    throw UserError(a.scan + ": " + e.what());
  }
  const wavelet::Alignment& al = scan.aligned.alignment;
  wavelet::SymmetrizeOptions so;
  so.merge_distance = a.merge_distance;
  wavelet::Symmetrized sym = wavelet::symmetrize(scan.cloud, al, so);
  sym.cloud.source = a.scan;
  if (ends_with(a.output, ".ply")) {
    write_point_cloud_ply(a.output, sym.cloud);
  } else {
    write_point_cloud_xyz(a.output, sym.cloud);
  }
  std::optional<Vec3> known;
  if (!a.scanner.empty())
    known = parse_scanner(a.scanner);
  else if (scan.cloud.scanner)
    known = scan.cloud.scanner;
  double reach = 0;
  for (const Vec3& p : scan.aligned.points) reach = std::max(reach, std::abs(p.y));
  const Vec3 s = equivalent_scanner(al, known, 2 * reach);
  std::printf("%s: %zu points + %zu reflected (%zu on the plane or duplicates merged) = %zu\n",
              file_name(a.scan).c_str(), scan.cloud.size(), sym.reflected, sym.merged,
              sym.cloud.size());
  std::printf("plane through the root (%s, %s, %s) with normal (%s, %s, 0)\n",
              shortest_text(al.root.x).c_str(), shortest_text(al.root.y).c_str(),
              shortest_text(al.root.z).c_str(), shortest_text(al.scanner_dir.x).c_str(),
              shortest_text(al.scanner_dir.y).c_str());
  std::printf("to align the output the same way, pass --scanner %s,%s,%s\n",
              shortest_text(s.x).c_str(), shortest_text(s.y).c_str(), shortest_text(s.z).c_str());
  return 0;
}

}  // namespace

void add_symmetrize(CLI::App& app, const GlobalOptions& global, std::function<int()>& run) {
  auto args = std::make_shared<SymmetrizeArgs>();
  CLI::App* sub = app.add_subcommand(
      "symmetrize",
      "merge a scan with its reflection about the scanner plane through the root (preprocessing)");
  sub->add_option("SCAN", args->scan, "point cloud (.ply .xyz .txt .asc .las .laz .pcd)")
      ->required();
  output_path(sub->add_option("-o,--output", args->output, "output points, .ply or .xyz"))
      ->required();
  sub->add_option("--scanner", args->scanner, "scanner position x,y,z (default: from the file)");
  sub->add_option("--merge-distance", args->merge_distance,
                  "drop reflections this close to an input point (default: 1e-6 of the extent)")
      ->check(CLI::NonNegativeNumber);
  sub->callback(
      [args, &global, &run] { run = [args, &global] { return run_symmetrize(*args, global); }; });
}

}  // namespace ramus::cli
