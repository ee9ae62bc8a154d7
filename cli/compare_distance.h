// The positional part of `ramus compare --within D,...`: how much of B's skeleton lies within each
// distance of A's (precision: the share of B's length), and of A's within it of B's (recall),
// with the lengths and tip counts. This is the measure of skeleton reconstruction against a
// reference skeleton of the same tree (issue 19's table: the share of a method's skeleton within
// 5 / 10 / 20 cm of the hand-made reference); both sides must be that one tree, in the same
// coordinates: skeleton files (.json) or scans (reconstructed), not grammars.
#pragma once

#include <vector>

#include "cli/compare_side.h"

namespace ramus::cli {

struct DistanceRow {
  double within = 0;     // in the sources' units
  double precision = 0;  // share of B's samples within `within` of A's skeleton
  double recall = 0;     // share of A's samples within `within` of B's skeleton
};

struct DistanceReport {
  double step = 0;  // sampling step along both skeletons' segments
  std::vector<DistanceRow> rows;
  double length_a = 0, length_b = 0;
  std::size_t tips_a = 0, tips_b = 0;
};

// `within` holds positive distances, ascending. Both skeletons are sampled every fifth of the
// smallest distance (a sample's nearest neighbour on the other side is then at most a tenth of
// it farther than the other skeleton's segment).
DistanceReport measure_distances(const CompareSide& a, const CompareSide& b,
                                 const std::vector<double>& within);

void print_distance_report(const DistanceReport& report);

}  // namespace ramus::cli
