// One vertex's skin binding as glTF wants it (the pieces' glTF writer, gltf_pieces.cpp): no
// joint twice among the non-zero weights, unused slots joint 0 with weight 0, float weights
// summing to one.
#pragma once

#include <array>
#include <cstdint>

namespace ramus::pieces {

struct SkinVertex {
  std::array<std::uint32_t, 4> joints{0, 0, 0, 0};
  std::array<float, 4> weights{0, 0, 0, 0};
};

// The binding of a vertex with piece-local `joints` and `weights`, its joints offset by
// `offset`; an unbound vertex follows joint `offset` (the piece's root joint).
SkinVertex normalize_skin(const std::array<std::uint16_t, 4>& joints,
                          const std::array<float, 4>& weights, std::uint32_t offset);

}  // namespace ramus::pieces
