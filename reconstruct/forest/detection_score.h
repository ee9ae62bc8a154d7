// Tree detection quality on a plot with known trees (docs/scale.md): trees found against the
// truth by their bases, with the categories of the TLS benchmarks (Liang et al. 2018,
// "International benchmarking of terrestrial laser scanning approaches for forest inventories",
// ISPRS J. Photogramm. 144): matched, missed (omission), merged, split and false (commission).
#pragma once

#include <cstddef>
#include <vector>

#include "core/skeleton.h"

namespace ramus::forest {

struct DetectionScore {
  std::size_t truth = 0, detected = 0;
  std::size_t matched = 0;      // one to one, bases within the match distance
  std::size_t missed = 0;       // truth trees neither matched nor merged into another
  std::size_t merged = 0;       // truth trees whose wood went to a tree matched to another
  std::size_t split = 0;        // detected trees that are a piece of a matched truth tree
  std::size_t false_trees = 0;  // detected trees that are neither matched nor split pieces
  double mean_base_error = 0, max_base_error = 0;  // over matched pairs, horizontal
  double precision = 0, recall = 0, f_score = 0;
};

// A base is a tree's root. Greedy one-to-one matching by increasing horizontal distance up to
// `match_distance`. For the rest, nodes are assigned to the nearest node of the other side within
// `near` (merged: most of a truth tree's nodes lie on one detected tree matched elsewhere; split:
// most of a detected tree's nodes lie on a truth tree matched elsewhere).
DetectionScore score_detection(const std::vector<Skeleton>& truth,
                               const std::vector<Skeleton>& detected, double match_distance = 0.5,
                               double near = 0.3);

}  // namespace ramus::forest
