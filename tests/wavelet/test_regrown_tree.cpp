// The tree an inferred wavelet grammar regrows (its `derive 1` from the axiom dyad) is one tree:
// one root at the base and every segment joined to it through parent links (no pen-up gap),
// nothing below the base, radii that never grow outwards, no internode longer than a third of
// the scan's height, and at most 10 % of its length along a grid axis (segments between cell
// centroids, not lattice offsets). Properties over many seeds of the synthetic tree and over
// every readable real scan.
#include <catch2/catch.hpp>
#include <filesystem>

#include "core/rng.h"
#include "formats/point_cloud_io.h"
#include "fractal_cloud.h"
#include "infer/shape/envelope.h"
#include "infer/shape/tree_shape.h"
#include "infer/wavelet/infer_grammar.h"
#include "reconstruct/reconstruct.h"
#include "regrown_tree_util.h"

using namespace ramus;
using namespace ramus::wavelet;
using namespace ramus::wavelet::test;

namespace {

double cloud_height(const AlignedCloud& c) {
  double lo = c.points[0].z, hi = lo;
  for (const Vec3& p : c.points) {
    lo = std::min(lo, p.z);
    hi = std::max(hi, p.z);
  }
  return hi - lo;
}

Skeleton check_one_tree(const AlignedCloud& cloud, const WaveletInferOptions& o) {
  const WaveletInference r = infer_wavelet_grammar(cloud, o);
  Skeleton grown = grow_text(r.ramus_text);
  const TreeShape t = shape_of(grown);
  const shape::TreeShape whole = shape::measure_tree_shape(grown);
  const double h = cloud_height(cloud);
  INFO("roots " << t.roots << ", length " << t.length << ", axis-locked " << whole.axis_locked_share
                << ", longest " << t.longest << " of height " << h << ", lowest " << t.lowest
                << ", widest child " << t.widest_child);
  CHECK(t.roots == 1);
  CHECK(whole.pieces == 1);
  CHECK(t.length > 0);
  CHECK(t.lowest >= -1e-5 * h);  // the text writes 6 significant digits
  CHECK(t.widest_child <= 1.05);
  CHECK(t.longest <= h / 3);
  CHECK(whole.axis_locked_share <= 0.10);
  // The regrown tree reaches most of the scan's height.
  CHECK(t.height >= 0.8 * h);
  return grown;
}

// The reconstruction's envelope IoU against its scan: the tree with the most length.
double reconstruction_iou(const PointCloud& scan) {
  const ReconstructResult r = reconstruct(scan);
  REQUIRE(!r.trees.empty());
  const Skeleton* best = &r.trees.front();
  for (const Skeleton& s : r.trees)
    if (s.total_length() > best->total_length()) best = &s;
  return shape::envelope_iou(scan, *best);
}

}  // namespace

TEST_CASE("regrown wavelet tree: one piece from one root over many synthetic trees",
          "[wavelet][regrown]") {
  for (std::uint64_t seed = 1; seed <= 12; ++seed) {
    INFO("seed " << seed);
    const AlignedCloud cloud = fractal_tree_cloud(seed, seed % 2 ? 5 : 6);
    WaveletInferOptions o;
    o.grid = seed % 3 == 0 ? 32 : 64;
    o.seed = seed;
    check_one_tree(cloud, o);
  }
}

TEST_CASE("regrown wavelet tree: one piece from one root on every readable real scan",
          "[wavelet][regrown]") {
  for (const char* name : {"adtree_tree1.xyz", "adtree_ahn3_delft.xyz", "plantscan3d_A3B4.asc",
                           "pytlidar_tree_1.las", "rtwig_cloud.txt"}) {
    const std::string path = std::string(RAMUS_SHARED_DIR) + "/data/" + name;
    if (!std::filesystem::exists(path)) {
      WARN("skipped: " << path << " is missing");
      continue;
    }
    INFO(name);
    const PointCloud scan = read_point_cloud(path);
    const AlignedCloud cloud = align_cloud(scan);
    const double reference = reconstruction_iou(scan);
    const double lean = shape::lean_degrees(scan);
    for (int grid : {64, 128}) {
      INFO("grid " << grid);
      WaveletInferOptions o;
      o.grid = grid;
      const Skeleton grown = check_one_tree(cloud, o);
      // The grown tree stands in the aligned frame, the scan where it was scanned: the envelope
      // and the lean are measured from each one's own base. Measured at 64 / 128 (in the order
      // above): 0.89 / 0.85, 0.93 / 0.90, 0.83 / 0.92, 0.91 / 0.93, 0.79 / 0.88 against the
      // reconstructions' 0.86, 0.56, 0.88, 0.94, 0.89. The reconstruction of rtwig_cloud (a twig
      // 1 m long) rose from 0.86 when the tips walked on to their last samples
      // (docs/reconstruction.md, The pipeline, step 7); on a 64 grid the wavelet tree of it is at
      // 0.88 of that, on a 128 grid at 0.99.
      const double iou = shape::envelope_iou(scan, grown);
      INFO("envelope IoU " << iou << ", reconstruction " << reference);
      CHECK(iou >= (grid == 64 ? 0.85 : 0.9) * reference);
      CHECK(iou >= 0.5);
      CHECK(std::abs(shape::lean_degrees(grown) - lean) <= 10);
    }
  }
}

TEST_CASE("regrown wavelet tree: the same scan and seed give the same bytes",
          "[wavelet][regrown]") {
  const AlignedCloud cloud = fractal_tree_cloud(7);
  WaveletInferOptions o;
  o.seed = 3;
  CHECK(infer_wavelet_grammar(cloud, o).ramus_text == infer_wavelet_grammar(cloud, o).ramus_text);
}

TEST_CASE("regrown wavelet tree: a conifer's trunk runs from the foot to the top",
          "[wavelet][regrown]") {
  // A straight vertical trunk 10 high (points on its bark) with a whorl of 5 horizontal
  // branches every metre, shorter towards the top: the trunk has no significant coefficient in
  // any dyad, and the dyad trees alone joined the whorls through their branch tips.
  PointCloud scan;
  ramus::Rng rng(3);
  auto add = [&](const Vec3& p) { scan.positions.push_back(Vec3f(p)); };
  for (int i = 0; i < 600; ++i) {  // a thin trunk, half hidden by the whorls
    const double z = rng.uniform(0, 10), a = rng.uniform(0, 3.1416);
    add({0.08 * std::cos(a), 0.08 * std::sin(a), z});
  }
  for (int w = 1; w <= 9; ++w) {
    const double z = w, reach = 3.0 * (10 - z) / 9;
    for (int b = 0; b < 5; ++b) {
      const double a = b * 1.2566 + w * 0.5;
      for (int i = 0; i < 150; ++i) {
        const double r = rng.uniform(0.1, reach);
        // drooping towards the tips, as spruce branches do
        add({r * std::cos(a), r * std::sin(a), z - 0.05 * r * r + rng.uniform(-0.03, 0.03)});
      }
    }
  }
  const AlignedCloud cloud = align_cloud(scan);
  WaveletInferOptions o;
  o.grid = 64;
  const Skeleton grown = check_one_tree(cloud, o);
  // Nodes near the trunk's axis reach the top (within a cell of the finest dyad of the axis).
  const Vec3 root = grown.nodes[grown.roots().front()].position;
  const double cell = 2 * 10.0 / 64;
  double top_on_axis = 0, top = 0;
  for (const SkeletonNode& n : grown.nodes) {
    top = std::max(top, n.position.z - root.z);
    if (std::hypot(n.position.x - root.x, n.position.y - root.y) <= 1.5 * cell)
      top_on_axis = std::max(top_on_axis, n.position.z - root.z);
  }
  INFO("top " << top << ", top on the axis " << top_on_axis);
  CHECK(top_on_axis >= 0.9 * top);
  CHECK(shape::lean_degrees(grown) <= 10);
}
