// The "alpha,beta" text of `--merge` (degrees) as MergeOptions.
#pragma once

#include <string_view>

#include "reconstruct/merge/branch_merge.h"

namespace ramus::merge {

// Parses "ALPHA,BETA" (two finite non-negative numbers of degrees, e.g. "10,15"). Throws
// std::invalid_argument saying what is wrong otherwise.
MergeOptions parse_merge_angles(std::string_view text);

}  // namespace ramus::merge
