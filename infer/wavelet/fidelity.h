// How close a tree regenerated from an inferred grammar is to the scan it was inferred from
// (Friedman & Stamos 2013 claim that the grammar "can reproduce that tree, and others like it,
// with sub-voxel accuracy"; abstract and IV-E).
//
// The regenerated tree is what the grammar file of infer_grammar.h grows into: lowered, derived
// for its `derive` steps (one step from the axiom dyad to the next finer one) and walked by the
// turtle, in the aligned frame of III-A (root at the origin, metres). Two measures:
// - voxel IoU at the input resolution: the input's occupied voxels against the voxels the
//   regenerated skeleton's segments pass through, in the same cube;
// - Chamfer distance between MST skeletons: the input's skeleton is the spanning tree of the dyad
//   the regenerated tree reproduces (III-E, dyad axiom_level + derive steps); both skeletons are
//   sampled along their segments and the mean nearest-point distance is taken both ways.
// Distances are in voxels of the input grid, so "sub-voxel" reads as a Chamfer distance below 1.
//
// The grammar draws its trunk from the origin (the scan's lowest point) to the root of the axiom
// dyad's spanning tree (infer_grammar.h), so the regenerated tree is compared where it grows.
#pragma once

#include <cstddef>
#include <vector>

#include "core/skeleton.h"
#include "core/vec3.h"
#include "infer/wavelet/alignment.h"
#include "infer/wavelet/infer_grammar.h"
#include "infer/wavelet/voxel_grid.h"

namespace ramus::wavelet {

// Points along every segment of `s` (parent -> node), at most `step` apart, both ends included.
// A skeleton with a single node gives that node.
std::vector<Vec3> sample_skeleton(const Skeleton& s, double step);

// The voxels of a cube shaped like `like` (origin, voxel size, side) that hold a sample of the
// skeleton's segments (spacing a quarter voxel): 1 there, 0 elsewhere. Samples outside the cube
// are counted in `outside` when given.
VoxelGrid voxelize_skeleton(const Skeleton& s, const VoxelGrid& like,
                            std::size_t* outside = nullptr);

struct ChamferDistance {
  double a_to_b = 0;  // mean distance from a point of A to the nearest point of B
  double b_to_a = 0;
  double mean = 0;       // (a_to_b + b_to_a) / 2, the symmetric Chamfer distance
  double hausdorff = 0;  // the largest of all nearest-point distances, both ways
};

// Chamfer distance between two point sets (nanoflann k-d trees). Throws std::invalid_argument
// when either is empty.
ChamferDistance chamfer_distance(const std::vector<Vec3>& a, const std::vector<Vec3>& b);

struct Fidelity {
  std::size_t grid_side = 0;
  double voxel_size = 0;                // metres
  int compared_dyad = 0;                // the dyad whose spanning tree is the input skeleton
  std::size_t input_voxels = 0;         // occupied voxels of the scan
  std::size_t regenerated_voxels = 0;   // voxels the regenerated tree passes through
  std::size_t regenerated_outside = 0;  // samples of the regenerated tree outside the cube
  double voxel_iou = 0;
  std::size_t input_nodes = 0, regenerated_nodes = 0;
  ChamferDistance chamfer;  // in voxels of the input grid
  double root_offset = 0;   // distance between the two skeletons' roots, voxels
  double regenerate_seconds = 0;
};

// Grows the grammar text of an inference (lowering errors and derivation failures throw
// std::runtime_error with the first diagnostic).
Skeleton regenerate_tree(const WaveletInference& inference);

// Measures the fidelity of `inference`, made by infer_wavelet_grammar(cloud, options).
Fidelity measure_fidelity(const AlignedCloud& cloud, const WaveletInferOptions& options,
                          const WaveletInference& inference);

// The same with an already regenerated tree (for callers that time or reuse it).
Fidelity measure_fidelity(const AlignedCloud& cloud, const WaveletInferOptions& options,
                          const WaveletInference& inference, const Skeleton& regenerated);

}  // namespace ramus::wavelet
