// Fidelity of inferred grammars (fidelity.h): the Chamfer distance and the skeleton voxelization
// against hand-computed answers, and the whole measure on a real scan and on a grammar tree
// scanned by the simulated scanner.
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <string>

#include "backends/scanner/scanner.h"
#include "compiler/derive.h"
#include "compiler/grow.h"
#include "compiler/pipeline.h"
#include "compiler/turtle.h"
#include "core/rng.h"
#include "formats/point_cloud_io.h"
#include "grammar/diagnostic.h"
#include "grammar/source.h"
#include "infer/wavelet/dyad_tree.h"
#include "infer/wavelet/fidelity.h"
#include "infer/wavelet/haar.h"
#include "infer/wavelet/isolated_points.h"
#include "infer/wavelet/tree_hierarchy.h"
#include "infer/wavelet/voxelize.h"
#include "tests/support/harness.h"

using namespace ramus;
using namespace ramus::wavelet;

namespace {

Skeleton chain(const std::vector<Vec3>& points) {
  Skeleton s;
  for (std::size_t i = 0; i < points.size(); ++i) {
    SkeletonNode n;
    n.position = points[i];
    n.parent = i == 0 ? kNoParent : std::uint32_t(i - 1);
    s.add(n);
  }
  return s;
}

// The grammar text's tree after `steps` derivation steps (0: the axiom alone).
Skeleton grow_text(const std::string& text, int steps) {
  SourceManager sources;
  DiagnosticSink diagnostics;
  const ir::Grammar g = lower_text("inferred.ramus", text, GrowOptions{}, sources, diagnostics);
  DeriveOptions d;
  d.steps = steps;
  TurtleOptions t;
  t.seed = g.settings.seed;
  t.steps = steps;
  return interpret(g, derive(g, d), t);
}

PointCloud scanned_grammar_tree() {
  SourceManager sources;
  DiagnosticSink diagnostics;
  const Skeleton truth =
      grow_file(std::string(RAMUS_SOURCE_DIR) + "/examples/abop/fig2_6a_monopodial.ramus",
                GrowOptions{}, sources, diagnostics);
  scanner::ScanOptions so;
  so.from = scanner::stations_around(truth, 1);
  so.noise = 0.005;
  return scanner::scan_skeleton(truth, so).cloud;
}

}  // namespace

TEST_CASE("fidelity: Chamfer distance of known point sets", "[wavelet][fidelity]") {
  const std::vector<Vec3> a{{0, 0, 0}, {1, 0, 0}}, b{{0, 0, 0}, {1, 0, 0}};
  CHECK(chamfer_distance(a, b).mean == 0);
  CHECK(chamfer_distance(a, b).hausdorff == 0);
  // A has one extra point 3 away: A -> B averages (0 + 0 + 3) / 3, B -> A is 0.
  const std::vector<Vec3> c{{0, 0, 0}, {1, 0, 0}, {4, 0, 0}};
  const ChamferDistance d = chamfer_distance(c, b);
  CHECK(d.a_to_b == Approx(1.0));
  CHECK(d.b_to_a == 0);
  CHECK(d.mean == Approx(0.5));
  CHECK(d.hausdorff == Approx(3.0));
  // A translation by t of a single point: distance |t| both ways.
  Rng rng(3);
  for (int i = 0; i < 50; ++i) {
    const Vec3 p{rng.uniform(-9, 9), rng.uniform(-9, 9), rng.uniform(-9, 9)};
    const Vec3 t{rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)};
    CHECK(chamfer_distance({p}, {p + t}).mean == Approx(length(t)));
  }
  CHECK_THROWS_AS(chamfer_distance({}, b), std::invalid_argument);
}

TEST_CASE("fidelity: segments are sampled at most a step apart, ends included",
          "[wavelet][fidelity]") {
  const Skeleton s = chain({{0, 0, 0}, {0, 0, 1}, {0.5, 0, 1}});
  const std::vector<Vec3> pts = sample_skeleton(s, 0.3);
  REQUIRE(pts.size() == 1 + 4 + 2);  // root, ceil(1 / 0.3) = 4, ceil(0.5 / 0.3) = 2
  CHECK(pts.front() == Vec3{0, 0, 0});
  CHECK(pts.back() == Vec3{0.5, 0, 1});
  for (std::size_t i = 1; i < pts.size(); ++i) CHECK(distance(pts[i - 1], pts[i]) <= 0.3 + 1e-12);
  CHECK_THROWS_AS(sample_skeleton(s, 0), std::invalid_argument);
}

TEST_CASE("fidelity: a segment along voxel centres marks exactly its voxels",
          "[wavelet][fidelity]") {
  VoxelGrid like(3);  // 8^3, voxels of 0.5 from (-2, -2, 0)
  like.origin = {-2, -2, 0};
  like.voxel_size = 0.5;
  // Along x through the centres of the voxels (1..6, 2, 3), then out of the cube.
  const Skeleton s = chain({like.centre(1, 2, 3), like.centre(6, 2, 3), {10, -1.75, 1.75}});
  std::size_t outside = 0;
  const VoxelGrid g = voxelize_skeleton(s, like, &outside);
  CHECK(outside > 0);
  for (std::size_t x = 1; x <= 6; ++x) CHECK(g.at(x, 2, 3) == 1.0);
  CHECK(g.at(7, 2, 3) == 1.0);  // the segment leaving the cube crosses the last voxel
  CHECK(g.count_above(0) == 7);
  CHECK(voxel_iou(g, 0, g, 0) == 1.0);
}

// A level tree of tree_hierarchy.h as a Skeleton (node i is node i).
Skeleton level_skeleton(const LevelTree& t) {
  Skeleton s;
  for (const HierarchyNode& h : t.nodes) {
    SkeletonNode n;
    n.position = h.position;
    s.nodes.push_back(n);
  }
  for (std::size_t i = 0; i < t.nodes.size(); ++i) s.nodes[i].parent = t.nodes[i].parent;
  return s;
}

TEST_CASE("fidelity: the axiom is the axiom dyad's joined tree and one step regrows the next one",
          "[wavelet][fidelity]") {
  const std::string scan = std::string(RAMUS_SHARED_DIR) + "/data/rtwig_cloud.txt";
  if (!std::filesystem::exists(scan)) {
    WARN("skipped: " << scan << " is missing");
    return;
  }
  const AlignedCloud aligned = align_cloud(read_point_cloud(scan));
  WaveletInferOptions o;
  o.grid = 32;
  const WaveletInference r = infer_wavelet_grammar(aligned, o);
  // The trees of tree_hierarchy.h, built as the inference builds them.
  const AlignedCloud kept = without_isolated_points(aligned).value_or(aligned);
  VoxelizeOptions vo;
  vo.levels = 5;
  const VoxelGrid grid = voxelize(kept, vo);
  const WaveletPyramid pyramid = haar_forward(grid, Decomposition::nonstandard);
  DyadTreeOptions to;
  to.threshold = o.mst_threshold;
  const std::vector<LevelTree> trees = tree_hierarchy(dyad_trees(pyramid, to), kept, grid);
  const double step = 0.25 * grid.voxel_size;
  // The axiom, grown without any derivation step from the turtle's start (the base), is tree
  // L-2 itself: the Chamfer measure of a perfect copy is 0 (6-digit numbers in the text).
  const Skeleton axiom = grow_text(r.ramus_text, 0);
  REQUIRE(!axiom.empty());
  const ChamferDistance c =
      chamfer_distance(sample_skeleton(level_skeleton(trees[std::size_t(r.axiom_level)]), step),
                       sample_skeleton(axiom, step));
  CHECK(c.mean / grid.voxel_size < 0.01);
  CHECK(c.hausdorff / grid.voxel_size < 0.05);
  // One step: every vector of the axiom takes its own production unless its key equals an
  // earlier one's, so the regrown tree is tree L-1 up to those few.
  const Skeleton grown = grow_text(r.ramus_text, 1);
  const ChamferDistance d =
      chamfer_distance(sample_skeleton(level_skeleton(trees[std::size_t(r.axiom_level) + 1]), step),
                       sample_skeleton(grown, step));
  INFO("rules " << r.l_rules << ", productions " << r.productions << ", Chamfer " << d.mean);
  if (r.productions == r.l_rules) {
    CHECK(d.mean / grid.voxel_size < 0.01);
  } else {
    CHECK(d.mean / grid.voxel_size < 0.5);
  }
}

TEST_CASE("fidelity: one derivation step stays within about a voxel of the finer dyad's tree",
          "[wavelet][fidelity]") {
  // Successors drawn from their own start in the predecessor's box, the turtle moved on to the
  // predecessor's end after them, and the trunk from the lowest point: the regenerated tree
  // (not translated) lies close to the input's spanning tree. A grammar that left the turtle at
  // the tip of the last successor, or drew every successor from the predecessor's start, or
  // started the axiom at the lowest point, lands 4-70 voxels away with an IoU below 0.05.
  struct Case {
    std::string name;
    AlignedCloud cloud;
    int grid;
  };
  std::vector<Case> cases{{"scanned monopodial", align_cloud(scanned_grammar_tree()), 64}};
  const std::string scan = std::string(RAMUS_SHARED_DIR) + "/data/rtwig_cloud.txt";
  if (std::filesystem::exists(scan)) {
    cases.push_back({"rtwig", align_cloud(read_point_cloud(scan)), 64});
  }
  for (const Case& k : cases) {
    WaveletInferOptions o;
    o.grid = k.grid;
    const WaveletInference r = infer_wavelet_grammar(k.cloud, o);
    const Fidelity f = measure_fidelity(k.cloud, o, r);
    INFO(k.name << ": Chamfer " << f.chamfer.mean << " (in->regen " << f.chamfer.a_to_b
                << ", regen->in " << f.chamfer.b_to_a << "), IoU " << f.voxel_iou);
    CHECK(f.chamfer.mean < 2.0);
    CHECK(f.chamfer.a_to_b < 2.0);
    CHECK(f.chamfer.b_to_a < 2.0);
    CHECK(f.voxel_iou > 0.05);
    CHECK(f.regenerated_outside == 0);
  }
}

TEST_CASE("fidelity: a real scan and a scanned grammar tree give consistent, repeatable figures",
          "[wavelet][fidelity]") {
  const std::string scan = std::string(RAMUS_SHARED_DIR) + "/data/rtwig_cloud.txt";
  std::vector<PointCloud> clouds{scanned_grammar_tree()};
  if (std::filesystem::exists(scan)) clouds.push_back(read_point_cloud(scan));
  for (const PointCloud& cloud : clouds) {
    const AlignedCloud aligned = align_cloud(cloud);
    WaveletInferOptions o;
    o.grid = 32;
    const WaveletInference r = infer_wavelet_grammar(aligned, o);
    const Fidelity f = measure_fidelity(aligned, o, r);
    CHECK(f.grid_side == 32);
    CHECK(f.input_voxels == r.occupied_voxels);
    CHECK(f.compared_dyad == r.axiom_level + 1);
    CHECK(f.regenerated_nodes > 0);
    CHECK(f.input_nodes > 0);
    CHECK(f.voxel_iou >= 0);
    CHECK(f.voxel_iou <= 1);
    CHECK(f.chamfer.mean == Approx(0.5 * (f.chamfer.a_to_b + f.chamfer.b_to_a)));
    CHECK(f.chamfer.hausdorff >= std::max(f.chamfer.a_to_b, f.chamfer.b_to_a));
    // The same inputs, the same figures.
    const Fidelity again = measure_fidelity(aligned, o, r);
    CHECK(again.chamfer.mean == f.chamfer.mean);
    CHECK(again.voxel_iou == f.voxel_iou);
    // A perfect regeneration -- the input skeleton itself -- scores 0.
    VoxelizeOptions vo;
    vo.levels = 5;
    const WaveletPyramid pyramid =
        haar_forward(voxelize(without_isolated_points(aligned).value_or(aligned), vo),
                     Decomposition::nonstandard);
    DyadTreeOptions to;
    to.threshold = o.mst_threshold;
    const Skeleton input = to_skeleton(dyad_tree(pyramid, f.compared_dyad, to), pyramid, to);
    const Fidelity perfect = measure_fidelity(aligned, o, r, input);
    CHECK(perfect.chamfer.mean == 0);
    CHECK(perfect.root_offset == 0);
  }
}
