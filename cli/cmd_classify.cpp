// ramus classify SCAN -o OUT.ply|.las|.laz [--wood WOOD.ply|.xyz|.las|.laz] [--ascii] [--scale R]
// Separates the foliage of a laser scan from its wood (docs/wood-separation.md) and writes every
// point with a `wood` property (1 wood, 0 leaf) and its `leaf_score`, so the split can be
// inspected in any point-cloud viewer (in LAS/LAZ as named extra bytes, beside the scan's own
// intensity and classification); optionally the wood points alone, ready for
// `ramus reconstruct --leaves-in-scan keep`.
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>
#include <string>

#include "cli/command.h"
#include "cli/output_path.h"
#include "core/atomic_file.h"
#include "core/little_endian.h"
#include "core/number_text.h"
#include "formats/las_file.h"
#include "formats/point_cloud_io.h"
#include "reconstruct/wood/wood_separation.h"

namespace ramus::cli {
namespace {

struct ClassifyArgs {
  std::string scan, output, wood;
  bool ascii = false;
  double scale = 0;
};

// PLY with world coordinates in double precision, `wood` (uchar) and `leaf_score` (float).
std::string classified_ply(const PointCloud& c, const WoodSeparation& ws, bool binary) {
  std::string out = "ply\nformat ";
  out += binary ? "binary_little_endian 1.0\n" : "ascii 1.0\n";
  out += "comment ramus classify: wood 1 = wood, 0 = leaf (docs/wood-separation.md)\n";
  out += "element vertex " + std::to_string(c.size()) + "\n";
  out += "property double x\nproperty double y\nproperty double z\n";
  out += "property uchar wood\nproperty float leaf_score\nend_header\n";
  for (std::size_t i = 0; i < c.size(); ++i) {
    const Vec3 p = c.world(i);
    if (binary) {
      for (int k = 0; k < 3; ++k) append_little_endian(out, p[k]);
      append_little_endian(out, ws.wood[i]);
      append_little_endian(out, ws.leaf_score[i]);
      continue;
    }
    for (int k = 0; k < 3; ++k) {
      append_shortest(out, p[k]);
      out += ' ';
    }
    out += ws.wood[i] ? "1 " : "0 ";
    append_shortest(out, ws.leaf_score[i]);
    out += '\n';
  }
  return out;
}

bool is_las(const std::string& path) {
  const std::string e = std::filesystem::path(path).extension().string();
  return e == ".las" || e == ".laz";
}

// LAS 1.4 (or LAZ) with the scan's channels and `wood`, `leaf_score` as extra bytes.
void write_classified_las(const std::string& path, const PointCloud& c, const WoodSeparation& ws) {
  LasWriteOptions o;
  o.extra.push_back({"wood", "1 wood, 0 leaf", ws.wood, {}});
  o.extra.push_back({"leaf_score", "leaf likelihood (ramus classify)", {}, ws.leaf_score});
  write_point_cloud_las(path, c, o);
}

int run_classify(const ClassifyArgs& a, const GlobalOptions& global) {
  auto is_ply = [](const std::string& p) { return std::filesystem::path(p).extension() == ".ply"; };
  if (a.ascii && !is_ply(a.output) && !is_ply(a.wood)) {
    throw UserError("--ascii applies to PLY outputs only, not to " + a.output);
  }
  PointCloud cloud;
  try {
    cloud = read_point_cloud(a.scan);
  } catch (const FormatError& e) {
    throw UserError(e.what());
  }
  WoodOptions o;
  o.scale = a.scale;
  WoodSeparation ws;
  try {
    ws = separate_wood(cloud, o);
  } catch (const WoodError& e) {
    throw UserError(a.scan + ": " + e.what());
  }
  try {
    if (is_las(a.output)) {
      write_classified_las(a.output, cloud, ws);
    } else {
      write_file_atomically(a.output, classified_ply(cloud, ws, !a.ascii));
    }
    if (!a.wood.empty()) {
      const PointCloud wood = select_points(cloud, ws.wood);
      if (is_las(a.wood)) {
        write_point_cloud_las(a.wood, wood);
      } else if (std::filesystem::path(a.wood).extension() == ".xyz") {
        write_point_cloud_xyz(a.wood, wood);
      } else {
        write_point_cloud_ply(a.wood, wood, !a.ascii);
      }
    }
  } catch (const WriteError& e) {
    throw UserError(e.what());
  }
  for (const std::string& n : ws.notes) std::fprintf(stderr, "ramus: note: %s\n", n.c_str());
  if (!global.quiet) {
    std::fprintf(stderr,
                 "ramus: wrote %s (%zu points: %zu wood, %zu leaf = %.1f%%; scale %.3g, "
                 "Ashman's D %.2f)\n",
                 a.output.c_str(), cloud.size(), ws.finite_points - ws.leaf_points, ws.leaf_points,
                 100 * ws.leaf_fraction, ws.scale, ws.separation);
  }
  return 0;
}

CLI::Validator extension_check(std::vector<std::string> allowed, const std::string& what) {
  return CLI::Validator(
      [allowed, what](const std::string& p) -> std::string {
        const std::string e = std::filesystem::path(p).extension().string();
        for (const std::string& x : allowed) {
          if (e == x) return "";
        }
        return what;
      },
      "FILE", "output file");
}

}  // namespace

void add_classify(CLI::App& app, const GlobalOptions& global, std::function<int()>& run) {
  auto args = std::make_shared<ClassifyArgs>();
  CLI::App* sub = app.add_subcommand(
      "classify", "wood/leaf separation of a scan (points with a wood property)");
  sub->add_option("scan", args->scan, "point cloud: .ply, .xyz/.txt/.asc/.csv, .las, .laz, .pcd")
      ->required();
  output_path(sub->add_option("-o,--output", args->output,
                              "output .ply, .las or .laz: every point with `wood` (1 wood, 0 "
                              "leaf) and `leaf_score` (LAS 1.4 extra bytes in .las/.laz)"))
      ->required()
      ->check(
          extension_check({".ply", ".las", ".laz"}, "the output must end in .ply, .las or .laz"));
  output_path(sub->add_option("--wood", args->wood,
                              "also write the wood points alone (.ply, .xyz, .las or .laz)"))
      ->check(extension_check({".ply", ".xyz", ".las", ".laz"},
                              "the wood output must end in .ply, .xyz, .las or .laz"));
  sub->add_flag("--ascii", args->ascii, "write ascii PLY instead of binary (PLY outputs only)");
  sub->add_option("--scale", args->scale,
                  "neighbourhood radius r of the features (default: the larger of 1% of the "
                  "height and 6 point spacings)")
      ->check(CLI::NonNegativeNumber);
  sub->callback(
      [args, &global, &run] { run = [args, &global] { return run_classify(*args, global); }; });
}

}  // namespace ramus::cli
