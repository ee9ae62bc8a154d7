// Fidelity of an inferred grammar to its scan (see fidelity.h). Reference: S. Friedman and
// I. Stamos, "Automatic Procedural Modeling of Tree Structures in Point Clouds Using Wavelets",
// 3DV 2013 (the sub-voxel claim of the abstract; III-E for the spanning trees compared).
#include "infer/wavelet/fidelity.h"

#include <Eigen/Core>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include "compiler/derive.h"
#include "compiler/pipeline.h"
#include "compiler/turtle.h"
#include "grammar/diagnostic.h"
#include "grammar/source.h"
#include "reconstruct/bsg/kdtree.h"
#include "infer/wavelet/dyad_tree.h"
#include "infer/wavelet/haar.h"
#include "infer/wavelet/isolated_points.h"
#include "infer/wavelet/voxelize.h"

namespace ramus::wavelet {
namespace {

// Sampling of segments for the voxelization, in voxels: a quarter voxel cannot step over a voxel
// a segment passes through by more than a sliver.
constexpr double kVoxelSampling = 0.25;

std::vector<Eigen::Vector3d> to_eigen(const std::vector<Vec3>& pts) {
  std::vector<Eigen::Vector3d> out(pts.size());
  for (std::size_t i = 0; i < pts.size(); ++i) out[i] = {pts[i].x, pts[i].y, pts[i].z};
  return out;
}

// Mean and largest distance from each point of `from` to the nearest point of `index`.
std::pair<double, double> one_way(const std::vector<Eigen::Vector3d>& from,
                                  const bsg::PointIndex& index) {
  double sum = 0, worst = 0;
  for (const Eigen::Vector3d& p : from) {
    double d2 = 0;
    index.nearest(p, &d2);
    const double d = std::sqrt(d2);
    sum += d;
    worst = std::max(worst, d);
  }
  return {sum / double(from.size()), worst};
}

// The root of a skeleton: its first node without a parent.
Vec3 root_of(const Skeleton& s) {
  for (const SkeletonNode& n : s.nodes) {
    if (n.parent == kNoParent) return n.position;
  }
  return {};
}

}  // namespace

std::vector<Vec3> sample_skeleton(const Skeleton& s, double step) {
  if (!(step > 0)) throw std::invalid_argument("the sampling step must be positive");
  std::vector<Vec3> out;
  for (const SkeletonNode& n : s.nodes) {
    if (n.parent == kNoParent || n.parent >= s.nodes.size()) {
      out.push_back(n.position);
      continue;
    }
    const Vec3 a = s.nodes[n.parent].position, b = n.position;
    const int pieces = std::max(1, int(std::ceil(distance(a, b) / step)));
    // The parent's end was added with the parent (or its own segment); only (a, b] here.
    for (int k = 1; k <= pieces; ++k) out.push_back(a + (b - a) * (double(k) / pieces));
  }
  return out;
}

VoxelGrid voxelize_skeleton(const Skeleton& s, const VoxelGrid& like, std::size_t* outside) {
  VoxelGrid g(like.levels);
  g.origin = like.origin;
  g.voxel_size = like.voxel_size;
  std::size_t out = 0;
  for (const Vec3& p : sample_skeleton(s, kVoxelSampling * like.voxel_size)) {
    const Vec3 local = (p - g.origin) / g.voxel_size;
    const double x = std::floor(local.x), y = std::floor(local.y), z = std::floor(local.z);
    const double n = double(g.n);
    if (!(x >= 0 && y >= 0 && z >= 0 && x < n && y < n && z < n)) {
      ++out;
      continue;
    }
    g.at(std::size_t(x), std::size_t(y), std::size_t(z)) = 1.0;
  }
  if (outside) *outside = out;
  return g;
}

ChamferDistance chamfer_distance(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  if (a.empty() || b.empty()) {
    throw std::invalid_argument("the Chamfer distance needs two non-empty point sets");
  }
  const std::vector<Eigen::Vector3d> ea = to_eigen(a), eb = to_eigen(b);
  const bsg::PointIndex ia(ea), ib(eb);
  ChamferDistance c;
  const auto ab = one_way(ea, ib), ba = one_way(eb, ia);
  c.a_to_b = ab.first;
  c.b_to_a = ba.first;
  c.mean = 0.5 * (c.a_to_b + c.b_to_a);
  c.hausdorff = std::max(ab.second, ba.second);
  return c;
}

Skeleton regenerate_tree(const WaveletInference& inference) {
  SourceManager sources;
  DiagnosticSink diagnostics;
  const ir::Grammar g =
      lower_text("inferred.ramus", inference.ramus_text, GrowOptions{}, sources, diagnostics);
  TurtleOptions t;
  t.seed = g.settings.seed;
  t.steps = g.settings.derive;
  try {
    return interpret(g, derive(g, DeriveOptions{}), t);
  } catch (const DeriveError& e) {
    throw std::runtime_error(std::string("the inferred grammar does not derive: ") + e.what());
  }
}

Fidelity measure_fidelity(const AlignedCloud& cloud, const WaveletInferOptions& options,
                          const WaveletInference& inference) {
  const auto t0 = std::chrono::steady_clock::now();
  const Skeleton tree = regenerate_tree(inference);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  Fidelity f = measure_fidelity(cloud, options, inference, tree);
  f.regenerate_seconds = seconds;
  return f;
}

Fidelity measure_fidelity(const AlignedCloud& cloud, const WaveletInferOptions& options,
                          const WaveletInference& inference, const Skeleton& regenerated) {
  validate_options(options);
  VoxelizeOptions vo;
  vo.levels = levels_for_side(std::uint64_t(options.grid));
  vo.values = options.values;
  // The points the inference quantized: without the isolated ones (isolated_points.h).
  const std::optional<AlignedCloud> kept = without_isolated_points(cloud);
  const VoxelGrid grid = voxelize(kept ? *kept : cloud, vo);
  Fidelity f;
  f.grid_side = grid.n;
  f.voxel_size = grid.voxel_size;
  f.input_voxels = grid.count_above(0);

  // The input skeleton: the spanning tree of the dyad the derivation steps reach (one step from
  // the axiom dyad to the next finer one, by the file's `derive 1`; never beyond the finest).
  SourceManager sources;
  DiagnosticSink diagnostics;
  const int steps =
      lower_text("inferred.ramus", inference.ramus_text, GrowOptions{}, sources, diagnostics)
          .settings.derive;
  f.compared_dyad = std::min(inference.axiom_level + steps, vo.levels - 1);
  DyadTreeOptions to;
  to.threshold = options.mst_threshold;
  const WaveletPyramid pyramid = haar_forward(grid, Decomposition::nonstandard);
  const Skeleton input = to_skeleton(dyad_tree(pyramid, f.compared_dyad, to), pyramid, to);
  f.input_nodes = input.size();
  f.regenerated_nodes = regenerated.size();
  if (input.empty() || regenerated.empty()) {
    throw std::invalid_argument("a skeleton to compare is empty (input " +
                                std::to_string(input.size()) + " nodes, regenerated " +
                                std::to_string(regenerated.size()) + ")");
  }
  const VoxelGrid regrown = voxelize_skeleton(regenerated, grid, &f.regenerated_outside);
  f.regenerated_voxels = regrown.count_above(0);
  f.voxel_iou = voxel_iou(grid, 0, regrown, 0);

  const double step = kVoxelSampling * grid.voxel_size, v = grid.voxel_size;
  const std::vector<Vec3> in_samples = sample_skeleton(input, step);
  auto in_voxels = [v](ChamferDistance c) {
    return ChamferDistance{c.a_to_b / v, c.b_to_a / v, c.mean / v, c.hausdorff / v};
  };
  f.chamfer = in_voxels(chamfer_distance(in_samples, sample_skeleton(regenerated, step)));
  f.root_offset = distance(root_of(input), root_of(regenerated)) / v;
  return f;
}

}  // namespace ramus::wavelet
