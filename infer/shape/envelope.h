// The envelope of a tree: which cells of a (r, z) grid around its base it occupies, r the
// horizontal distance from the base's vertical axis and z the height above the base. Comparing
// two envelopes by intersection over union says how well a grown or reconstructed tree fills
// the volume of the scanned one, whatever its azimuth (docs/shape-measures.md).
//
// The reference (a scan, or a skeleton standing for one) sets the cell: its height H / 32.
// A scan occupies a cell when a point falls in it; a skeleton when one of its samples, taken
// every quarter cell (H / 128) along its segments, does. Each tree is placed at its own base
// (tree_base.h), found the same way from its points or samples.
#pragma once

#include <cstdint>
#include <vector>

#include "core/point_cloud.h"
#include "core/skeleton.h"
#include "infer/shape/tree_base.h"

namespace ramus::shape {

// Cells along the reference's height.
inline constexpr int kEnvelopeCells = 32;
// Skeleton samples per cell length.
inline constexpr int kSamplesPerCell = 4;

struct Envelope {
  TreeBase base;
  double cell = 0;  // cell size in r and z
  // Occupied cells, sorted and distinct: (r index << 32) | z index.
  std::vector<std::uint64_t> cells;
};

// The scan's envelope at cells of its own height / 32. Throws ShapeError for a scan without
// points or height.
Envelope scan_envelope(const PointCloud& scan);
// A skeleton as a reference: cells of its own height / 32. Throws ShapeError without height.
Envelope reference_envelope(const Skeleton& reference);
// A skeleton at a given cell size (the reference's). A skeleton without segments has no cells.
Envelope skeleton_envelope(const Skeleton& skeleton, double cell);

// |A n B| / |A u B|; 0 when both are empty.
double envelope_iou(const Envelope& a, const Envelope& b);

// The skeleton against the scan or the reference skeleton, at the reference's cells.
double envelope_iou(const PointCloud& scan, const Skeleton& skeleton);
double envelope_iou(const Skeleton& reference, const Skeleton& skeleton);
double envelope_iou(const Envelope& reference, const Skeleton& skeleton);

}  // namespace ramus::shape
