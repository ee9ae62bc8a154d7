// `ramus compare --picture OUT.png`: the scan's points, its reconstruction and the first grown
// trees side by side, from the front (top row, looking along +y: x right) and from the side
// (bottom row, looking along +x: -y right), every panel at one scale with each tree's base
// (infer/shape/tree_base.h, the base the envelope is measured from) at the bottom centre.
#pragma once

#include <string>
#include <vector>

#include "cli/compare_side.h"

namespace ramus::cli {

// Grown trees drawn per grammar side.
inline constexpr std::size_t kPictureSeeds = 3;

// Columns: for each side in order (A, B, then any more): a scan gives its points and its
// reconstruction, a grammar its first kPictureSeeds trees, a skeleton file its tree; the trees of
// successive sides in alternating colours. Written atomically; throws WriteError when the file
// cannot be written.
void write_compare_picture(const std::string& path, const std::vector<const CompareSide*>& sides);

}  // namespace ramus::cli
