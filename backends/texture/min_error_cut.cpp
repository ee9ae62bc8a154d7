#include "backends/texture/min_error_cut.h"

#include <limits>
#include <stdexcept>

namespace ramus::texture {

std::vector<int> min_error_cut(const std::vector<double>& error, int length, int depth, int lo,
                               int hi) {
  if (length <= 0 || lo < 0 || hi > depth || lo >= hi ||
      error.size() != std::size_t(length) * std::size_t(depth)) {
    throw std::invalid_argument("min_error_cut: bad band");
  }
  const double inf = std::numeric_limits<double>::infinity();
  // cost[i][j]: the least error of a path from step 0 to step i ending at j (Efros & Freeman's
  // E_ij = e_ij + min(E_{i-1,j-1}, E_{i-1,j}, E_{i-1,j+1})).
  std::vector<double> cost(error.size(), inf);
  for (int j = lo; j < hi; ++j) cost[std::size_t(j)] = error[std::size_t(j)];
  for (int i = 1; i < length; ++i) {
    for (int j = lo; j < hi; ++j) {
      double best = cost[std::size_t(i - 1) * depth + j];
      if (j > lo) best = std::min(best, cost[std::size_t(i - 1) * depth + j - 1]);
      if (j + 1 < hi) best = std::min(best, cost[std::size_t(i - 1) * depth + j + 1]);
      cost[std::size_t(i) * depth + j] = error[std::size_t(i) * depth + j] + best;
    }
  }
  // Trace back from the cheapest end.
  std::vector<int> cut(std::size_t(length), lo);
  int j = lo;
  for (int k = lo + 1; k < hi; ++k) {
    if (cost[std::size_t(length - 1) * depth + k] < cost[std::size_t(length - 1) * depth + j])
      j = k;
  }
  cut[std::size_t(length - 1)] = j;
  for (int i = length - 1; i > 0; --i) {
    int best = j;
    for (int k = std::max(lo, j - 1); k <= std::min(hi - 1, j + 1); ++k) {
      if (cost[std::size_t(i - 1) * depth + k] < cost[std::size_t(i - 1) * depth + best]) best = k;
    }
    j = best;
    cut[std::size_t(i - 1)] = j;
  }
  return cut;
}

}  // namespace ramus::texture
