#include "backends/pieces/skin_vertex.h"

namespace ramus::pieces {

SkinVertex normalize_skin(const std::array<std::uint16_t, 4>& joints,
                          const std::array<float, 4>& weights, std::uint32_t offset) {
  SkinVertex v;
  int used = 0;
  for (int s = 0; s < 4; ++s) {
    if (!(weights[s] > 0)) continue;
    const std::uint32_t j = offset + joints[s];
    int at = 0;
    while (at < used && v.joints[at] != j) ++at;
    if (at == used) {
      v.joints[used] = j;
      v.weights[used++] = weights[s];
    } else {
      v.weights[at] += weights[s];
    }
  }
  if (used == 0) {  // an unbound vertex follows the piece's root joint
    v.joints[0] = offset;
    v.weights[0] = 1;
    return v;
  }
  double sum = 0;
  for (int s = 0; s < used; ++s) sum += v.weights[s];
  int biggest = 0;
  for (int s = 0; s < used; ++s) {
    v.weights[s] = float(v.weights[s] / sum);
    if (v.weights[s] > v.weights[biggest]) biggest = s;
  }
  float rest = 0;
  for (int s = 0; s < used; ++s)
    if (s != biggest) rest += v.weights[s];
  v.weights[biggest] = 1.0f - rest;
  return v;
}

}  // namespace ramus::pieces
