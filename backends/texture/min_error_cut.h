// The minimum-error boundary cut of image quilting (Efros & Freeman 2001, section 2.1), which
// Burkus, Karpati & Szecsi use to stitch each bark tile's inside to its edge patterns (section
// 5.2): in the band where two images overlap, the path through the band with the least summed
// squared difference, found by dynamic programming. Pixels on one side of the path come from
// one image, pixels on the other side from the other, so the join runs where they agree.
#pragma once

#include <vector>

namespace ramus::texture {

// `error` holds length x depth values, error[i * depth + j]: the overlap error at step i along
// the band and j across it. Returns, for each step i, the cut c_i in [lo, hi) (0 <= lo < hi <=
// depth) minimising sum_i error[i][c_i] with |c_i - c_{i-1}| <= 1. Ties are broken by fixed
// rules, so the cut is deterministic. The caller reads c_i as the first pixel across that belongs
// to the second image.
std::vector<int> min_error_cut(const std::vector<double>& error, int length, int depth, int lo,
                               int hi);

}  // namespace ramus::texture
