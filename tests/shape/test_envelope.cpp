// The envelope IoU (infer/shape/envelope.h) on cases whose cells can be counted by hand.
#include <catch2/catch.hpp>

#include "infer/shape/edge_samples.h"
#include "infer/shape/envelope.h"
#include "infer/shape/shape_error.h"
#include "shape_fixtures.h"

using namespace ramus;
using namespace shape_test;

namespace {

// A small tree 8 high: trunk to 4, two branches and a leader. Powers of two keep every sample
// and cell boundary exact.
Skeleton small_tree() {
  Skeleton s;
  const std::uint32_t fork = chain(s, {0, 0, 0}, {0, 0, 4}, 2);
  chain(s, {0, 0, 4}, {2, 0, 6}, 3, fork);
  chain(s, {0, 0, 4}, {-1, 1.5, 7}, 2, fork);
  chain(s, {0, 0, 4}, {0.25, 0, 8}, 4, fork);
  return s;
}

}  // namespace

TEST_CASE("envelope: points sampled on a skeleton's edges give IoU 1", "[shape]") {
  const Skeleton tree = small_tree();
  // The scan is the skeleton's own samples at a quarter of the scan's cell: the same points,
  // the same base, the same cells.
  const std::vector<Vec3> samples = shape::sample_edges(tree, 8.0 / 128);
  const PointCloud scan = cloud_of(samples, {1000, -2000, 50});  // the offset must not matter
  CHECK(shape::envelope_iou(scan, tree) == 1.0);
  CHECK(shape::envelope_iou(tree, tree) == 1.0);
  // A scan denser than the samples sees a few more corner cells, no fewer.
  const PointCloud dense = cloud_of(shape::sample_edges(tree, 8.0 / 2048));
  const double iou = shape::envelope_iou(dense, tree);
  CHECK(iou > 0.85);
  CHECK(iou <= 1.0);
}

TEST_CASE("envelope: a tree in other cells gives 0", "[shape]") {
  // The scan is a pole on the base's axis (r = 0); the tree two poles 5 either side of its
  // own base (r = 5, cell 0.25: r index 20).
  Skeleton pole;
  chain(pole, {0, 0, 0}, {0, 0, 8}, 1);
  const PointCloud scan = cloud_of(shape::sample_edges(pole, 8.0 / 128));
  Skeleton apart;
  chain(apart, {5, 0, 0}, {5, 0, 8}, 1);
  chain(apart, {-5, 0, 0}, {-5, 0, 8}, 1);
  CHECK(shape::envelope_iou(scan, apart) == 0.0);
  const shape::Envelope e = shape::skeleton_envelope(apart, 0.25);
  CHECK(e.base.axis.x == 0.0);
  CHECK(e.cells.size() == 33);  // z cells 0..32, all at r index 20
  CHECK(e.cells.front() >> 32 == 20);
}

TEST_CASE("envelope: a half-height pole gives 17/33, and the other way round 33/65", "[shape]") {
  // Scan: a pole 8 high, cells 0.25: z indices 0..32 (the top point is in cell 32): 33 cells.
  // Tree: a pole 4 high sampled every 1/16: z indices 0..16: 17 cells, all shared.
  Skeleton full, half;
  chain(full, {0, 0, 0}, {0, 0, 8}, 1);
  chain(half, {3, 3, 1}, {3, 3, 5}, 1);  // where it stands does not matter
  const PointCloud scan = cloud_of(shape::sample_edges(full, 8.0 / 128));
  CHECK(shape::scan_envelope(scan).cells.size() == 33);
  CHECK(shape::envelope_iou(scan, half) == Approx(17.0 / 33).epsilon(1e-12));
  // Skeleton against skeleton: the reference (the half pole) sets the cell, 4 / 32 = 0.125,
  // so the full pole spans z indices 0..64 (65 cells) and shares 33.
  CHECK(shape::envelope_iou(half, full) == Approx(33.0 / 65).epsilon(1e-12));
  CHECK(shape::envelope_iou(full, half) == Approx(17.0 / 33).epsilon(1e-12));
}

TEST_CASE("envelope: the base is the lowest z and the mean x, y of the lowest 5 percent",
          "[shape]") {
  // Two poles 20 high starting at heights 0 and 0.5 (within 5 % = 1): both count.
  Skeleton s;
  chain(s, {2, 0, 0}, {2, 0, 20}, 1);
  chain(s, {-2, 4, 0.5}, {-2, 4, 20}, 1);
  const shape::Envelope e = shape::reference_envelope(s);
  CHECK(e.base.height == 20.0);
  CHECK(e.cell == 20.0 / 32);
  CHECK(e.base.axis.z == 0.0);
  // Samples every 20/128 = 0.15625: pole 1 has z = 0 .. 1 in 7 samples (0 .. 0.9375), pole 2
  // has z = 0.5 + k * 19.5/125 ... below 1: 4 samples (0.5, 0.656, 0.812, 0.968).
  CHECK(e.base.axis.x == Approx((7 * 2.0 + 4 * -2.0) / 11));
  CHECK(e.base.axis.y == Approx(4 * 4.0 / 11));
}

TEST_CASE("envelope: inputs without height are refused, an empty tree gives 0", "[shape]") {
  const PointCloud flat = cloud_of({{0, 0, 1}, {1, 0, 1}, {0, 1, 1}});
  CHECK_THROWS_AS(shape::scan_envelope(flat), shape::ShapeError);
  CHECK_THROWS_AS(shape::scan_envelope(PointCloud{}), shape::ShapeError);
  Skeleton lying;
  chain(lying, {0, 0, 0}, {5, 0, 0}, 2);
  CHECK_THROWS_AS(shape::reference_envelope(lying), shape::ShapeError);
  Skeleton pole;
  chain(pole, {0, 0, 0}, {0, 0, 8}, 1);
  const PointCloud scan = cloud_of(shape::sample_edges(pole, 0.5));
  CHECK(shape::envelope_iou(scan, Skeleton{}) == 0.0);
  // A tree a billion times the scan's height would need too many samples: an error, not a
  // memory exhaustion.
  Skeleton huge;
  chain(huge, {0, 0, 0}, {0, 0, 8e9}, 1);
  CHECK_THROWS_AS(shape::envelope_iou(scan, huge), shape::ShapeError);
}
