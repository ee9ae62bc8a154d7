// The shape part of `ramus compare`: the envelope IoU of B's trees against A (its scan points,
// or its trees), the reconstruction's own IoU as the reference line when A is a scan, and per
// tree its pieces, axis-locked share, height ratio and trunk lean (infer/shape/,
// docs/shape-measures.md).
#pragma once

#include <string>
#include <vector>

#include "cli/compare_side.h"

namespace ramus::cli {

struct ShapeRow {
  std::string label;  // "A reconstruction", "B seed 3", "B seed 3 vs A seed 3"
  double iou = 0;
  std::size_t pieces = 0;
  double largest_piece_share = 0;
  double axis_locked_share = 0;
  double height_ratio = 0;
  double lean_degrees = 0;     // NaN when undefined
  double lean_difference = 0;  // the tree's lean - the reference's; NaN when either is
};

struct ShapeReport {
  std::string reference;       // what the rows are measured against
  std::vector<ShapeRow> rows;  // the reconstruction of a scan A first, then B's trees
  bool has_reconstruction = false;
  double median_iou = 0;  // over B's rows
};

// Row i of B pairs B's tree i with A's tree i (a side with one tree is repeated); a scan A is
// the reference of every row. Throws UserError for inputs the measures cannot take.
ShapeReport measure_shapes(const CompareSide& a, const CompareSide& b);

void print_shape_report(const ShapeReport& report);

}  // namespace ramus::cli
