// Reconstruction benchmark and accuracy report (docs/reconstruction.md):
//   bench_reconstruct accuracy [FLAGS] GRAMMAR...  grammar tree -> simulated scans (1 and 3
//                                            stations, range noise 5 mm) -> reconstruct -> scores
//   bench_reconstruct time [FLAGS] SCAN...  reconstruction time of real scans
//   bench_reconstruct scene GRAMMAR N [--opt k=v]...  N trees of GRAMMAR scanned into one
//                                            ~1M-point cloud
// FLAGS (before the files they apply to): --noise S (metres), --density D, --leaves (scan the
// leaf cards too), --beam-divergence MRAD, --beam-diameter M, --range-resolution M,
// --registration-error M (as `ramus scan`: a beam of some width, stations registered with an
// error), --opt name=value (a ReconstructOptions field, for parameter sweeps: voxel,
// voxel_spacings, voxel_floor, neighbours, max_gap, hidden_limb_reach, contraction, iterations,
// overlap, min_branch, min_cylinder, ground_band, terrain, stray, stray_cluster, centre_lines,
// join_coincident, extend_tips),
// --stations N (only N stations instead of 1 and 3), --dump PREFIX (write the truth and the
// reconstruction as skeleton JSON, the scan as .xyz, and the truth samples of the radius classes
// with their centre-line errors as .centre.txt), --azimuth DEG (turn the tree by DEG about the
// vertical through its root before scanning: the stations see another side of it), --tree-seed N
// (grow the grammar, or the synthetic / thick tree, from seed N instead of its own), --repeat N
// (time: reconstruct each scan N times; cpu= is the least CPU time, user + system of all threads,
// of one reconstruction). Prints one line per run and the peak resident memory at the end.
#include <sys/resource.h>
#include <time.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>

#include "core/atomic_file.h"
#include "formats/point_cloud_io.h"
#include "formats/skeleton_json.h"
#include "mesh/tree_mesh.h"
#include "tests/reconstruct/reconstruct_fixtures.h"
#include "tests/support/harness.h"

using namespace ramus;

namespace {

// Options of a parameter sweep: --opt name=value.
void set_option(ReconstructOptions& o, const std::string& kv) {
  const auto eq = kv.find('=');
  if (eq == std::string::npos) throw std::runtime_error("--opt expects name=value, got " + kv);
  const std::string k = kv.substr(0, eq);
  const double v = std::atof(kv.c_str() + eq + 1);
  if (k == "voxel")
    o.voxel_size = v;
  else if (k == "voxel_spacings")
    o.voxel_spacings = v;
  else if (k == "voxel_floor")
    o.voxel_height_floor = v;
  else if (k == "neighbours")
    o.neighbours = int(v);
  else if (k == "max_gap")
    o.max_gap = v;
  else if (k == "hidden_limb_reach")
    o.hidden_limb_reach = v;
  else if (k == "contraction")
    o.contraction_steps = int(v);
  else if (k == "axis_levels")
    o.axis_levels = int(v);
  else if (k == "axis_linearity")
    o.axis_linearity = v;
  else if (k == "axis_passes")
    o.axis_passes = int(v);
  else if (k == "iterations")
    o.max_iterations = int(v);
  else if (k == "overlap")
    o.overlap_fraction = v;
  else if (k == "min_branch")
    o.min_branch_length = v;
  else if (k == "min_cylinder")
    o.min_cylinder_radius = v;
  else if (k == "ground_band")
    o.ground_band = v;
  else if (k == "centre_lines")
    o.centre_lines = v != 0;
  else if (k == "join_coincident")
    o.join_coincident = v != 0;
  else if (k == "extend_tips")
    o.extend_tips = v != 0;
  else if (k == "exponent")
    o.allometry_exponent = v;
  else if (k == "stray")
    o.remove_stray = v != 0;
  else if (k == "stray_cluster")
    o.stray_cluster = std::size_t(v);
  else if (k == "terrain")
    o.remove_terrain = v != 0;
  else
    throw std::runtime_error("unknown option " + k);
}

ReconstructOptions g_options;
std::vector<int> g_stations = {1, 3};  // --stations N: only N stations
std::string g_dump;    // --dump PREFIX: PREFIX<tree>-<stations>.truth.json, .rec.json, .scan.xyz,
                       // .centre.txt
int g_repeat = 1;      // --repeat N: time mode reconstructs each scan N times
double g_azimuth = 0;  // --azimuth DEG: the tree turned about its root's vertical
std::uint64_t g_tree_seed = 0;  // --tree-seed N: the tree's seed (0: the grammar's or fixture's)

// One line per truth sample of the radius classes: where the centre-line errors are, for drawing
// them over the truth, the reconstruction and the scan of the same dump.
void write_centre_samples(const std::string& path, const std::vector<CentreSample>& samples) {
  write_file_atomically(path, [&](std::ostream& out) {
    out << "# x y z dx dy dz radius error/radius seen\n";
    char line[256];
    for (const CentreSample& q : samples) {
      std::snprintf(line, sizeof line, "%.5f %.5f %.5f %.4f %.4f %.4f %.4f %.4f %d\n", q.position.x,
                    q.position.y, q.position.z, q.direction.x, q.direction.y, q.direction.z,
                    q.radius, q.error, int(q.seen));
      out << line;
    }
  });
}

void accuracy(const std::string& path, const scanner::HarnessCase& base) {
  // "synthetic": the thick-branched test tree of tests/reconstruct/reconstruct_fixtures.h;
  // "thick": its 14 m, 60 cm trunk variant (radii 5-60 cm), "thick-small" the 8 m, 30 cm one
  // the tests scan.
  // --tree-seed N grows another tree of the same kind: trees no parameter was chosen on.
  const auto seed = [](std::uint64_t own) { return g_tree_seed ? g_tree_seed : own; };
  Skeleton t = path == "synthetic"     ? test::synthetic_tree(seed(7), {0, 0, 0})
               : path == "thick"       ? test::thick_tree(seed(11), 14.0, 0.6)
               : path == "thick-small" ? test::thick_tree(seed(5), 8.0, 0.3)
                                       : scanner::grow_grammar(path, g_tree_seed);
  scanner::turn_about_root(t, g_azimuth);
  for (int stations : g_stations) {
    scanner::HarnessCase c = base;
    c.stations = stations;
    c.keep_samples = !g_dump.empty();
    PointCloud scanned;  // kept for --dump
    const scanner::HarnessResult r = scanner::run_harness(t, c, [&](const PointCloud& cloud) {
      if (!g_dump.empty()) scanned = cloud;
      return reconstruct(cloud, g_options);
    });
    const SkeletonComparison& a = r.at_radius;
    if (!g_dump.empty()) {
      const std::string stem =
          g_dump + std::filesystem::path(path).stem().string() + "-" + std::to_string(stations);
      write_skeleton_json(stem + ".truth.json", t);
      if (!r.reconstructed.empty()) write_skeleton_json(stem + ".rec.json", r.reconstructed[0]);
      write_point_cloud_xyz(stem + ".scan.xyz", scanned);
      write_centre_samples(stem + ".centre.txt", a.centre_samples);
    }
    std::printf(
        "%s stations=%d points=%zu trees=%zu precision(2r)=%.3f recall(2r)=%.3f "
        "precision(1%%h)=%.3f recall(1%%h)=%.3f chamfer=%.4f length=%.3f "
        "tips=%zu/%zu time=%.2fs\n  precision(1r)=%.3f recall(1r)=%.3f centre/r median=%.3f",
        path.c_str(), stations, r.points, r.trees, a.precision, a.recall, a.precision_distance,
        a.recall_distance, a.chamfer, a.length_ratio, a.branches_reconstructed, a.branches_truth,
        r.seconds, a.precision_1r, a.recall_1r, a.centre_error_median);
    for (const CentreError& e : a.centre_error) {
      if (e.samples == 0) continue;
      std::printf(" [%.0f-%.0f cm: %.3f, found %.3f, p90 %.2f, n=%zu]", 100 * e.lo, 100 * e.hi,
                  e.median, e.median_found, e.p90, e.samples);
    }
    // The same over the wood the scan saw (CompareOptions::scan).
    std::printf("\n  seen=%.3f recall(2r, seen)=%.3f centre/r median seen=%.3f", a.seen_fraction,
                a.recall_seen, a.centre_error_median_seen);
    for (const CentreError& e : a.centre_error) {
      if (e.seen == 0) continue;
      std::printf(" [%.0f-%.0f cm: %.3f, n=%zu]", 100 * e.lo, 100 * e.hi, e.median_seen, e.seen);
    }
    std::printf("\n");
  }
}

// CPU seconds (user + system, all threads) of this process so far.
double cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

// The reconstruction alone (the file is read once), g_repeat times; the stage times are those of
// the last run, cpu the least CPU time of one run (the machine is shared: the least is the one
// least disturbed by the other processes).
void time_scan(const std::string& path) {
  const PointCloud cloud = read_point_cloud(path);
  ReconstructResult r;
  double cpu = 1e300;
  for (int k = 0; k < std::max(1, g_repeat); ++k) {
    const double c0 = cpu_seconds();
    r = reconstruct(cloud, g_options);
    cpu = std::min(cpu, cpu_seconds() - c0);
  }
  std::printf(
      "%s points=%zu trees=%zu nodes=%zu bases=%.3f graph=%.3f forest=%.3f refine=%.3f "
      "inflate=%.3f total=%.3fs cpu=%.3fs\n",
      path.c_str(), cloud.size(), r.trees.size(), r.counts.skeleton_nodes, r.timings.bases,
      r.timings.graph, r.timings.forest, r.timings.refine, r.timings.inflate, r.timings.total, cpu);
}

void scene(const std::string& path, int n) {
  // N trees in a row, each from its own seed, meshed together and scanned from both sides.
  std::vector<Vec3> vertices;
  std::vector<std::uint32_t> indices;
  double height = 0, spacing = 0;
  for (int k = 0; k < n; ++k) {
    Skeleton s = scanner::grow_grammar(path, std::uint64_t(k + 1));
    Vec3 lo, hi;
    s.bounds(lo, hi);
    height = std::max(height, hi.z - lo.z);
    if (k == 0) spacing = 0.8 * std::max(hi.x - lo.x, hi.y - lo.y);
    for (auto& node : s.nodes) node.position.x += spacing * k;
    for (auto& o : s.organs) o.position.x += spacing * k;
    const mesh::TreeMesh m = mesh::build_tree_mesh(s, {});
    const auto base = std::uint32_t(vertices.size());
    for (const Vec3f& p : m.bark.positions) vertices.push_back(Vec3(p));
    for (std::uint32_t i : m.bark.indices) indices.push_back(base + i);
  }
  scanner::ScanOptions so;
  const double mid = spacing * (n - 1) / 2;
  so.from = {{mid, -2.0 * height, 0.02 * height}, {mid, 2.0 * height, 0.02 * height}};
  so.noise = 0.003 * height;
  so.density = 6000;
  const scanner::ScanResult scan = scanner::scan_triangles(vertices, indices, so);
  const ReconstructResult r = reconstruct(scan.cloud, g_options);
  std::printf(
      "scene of %d x %s: points=%zu trees=%zu nodes=%zu bases=%.3f graph=%.3f "
      "forest=%.3f refine=%.3f inflate=%.3f total=%.3fs\n",
      n, path.c_str(), scan.cloud.size(), r.trees.size(), r.counts.skeleton_nodes, r.timings.bases,
      r.timings.graph, r.timings.forest, r.timings.refine, r.timings.inflate, r.timings.total);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: bench_reconstruct accuracy|time FILE... | scene GRAMMAR N\n");
    return 2;
  }
  try {
    const std::string mode = argv[1];
    if (mode == "scene") {
      for (int i = 4; i + 1 < argc; i += 2) {
        if (std::strcmp(argv[i], "--opt") != 0) throw std::runtime_error("scene takes --opt only");
        set_option(g_options, argv[i + 1]);
      }
      scene(argv[2], argc > 3 ? std::atoi(argv[3]) : 4);
    } else {
      scanner::HarnessCase c;
      for (int i = 2; i < argc; ++i) {
        const std::string arg = argv[i];
        if (scanner::read_scan_flag(argc, argv, i, c)) {
          continue;
        } else if (arg == "--opt" && i + 1 < argc) {
          set_option(g_options, argv[++i]);
        } else if (arg == "--stations" && i + 1 < argc) {
          g_stations = {std::atoi(argv[++i])};
        } else if (arg == "--repeat" && i + 1 < argc) {
          g_repeat = std::atoi(argv[++i]);
        } else if (arg == "--azimuth" && i + 1 < argc) {
          g_azimuth = std::atof(argv[++i]);
        } else if (arg == "--tree-seed" && i + 1 < argc) {
          g_tree_seed = std::strtoull(argv[++i], nullptr, 10);
        } else if (arg == "--dump" && i + 1 < argc) {
          g_dump = argv[++i];
        } else if (arg == "--leaves") {
          c.leaves = true;
        } else if (mode == "time") {
          time_scan(arg);
        } else {
          accuracy(arg, c);
        }
      }
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_reconstruct: %s\n", e.what());
    return 1;
  }
  rusage ru{};
  getrusage(RUSAGE_SELF, &ru);
  std::printf("peak memory: %.1f MB\n", double(ru.ru_maxrss) / 1024.0);
  return 0;
}
