// Connected pieces of a skeleton: a grown tree should be one piece. The turtle's pen-up moves
// (`f`) and several roots start new pieces; a piece that starts where another one passes (an
// endpoint within 1e-6 of the height of another endpoint) is joined to it, since it draws as
// one.
#pragma once

#include <cstddef>
#include <vector>

#include "core/skeleton.h"

namespace ramus::shape {

inline constexpr double kTouchShare = 1e-6;  // endpoints this share of the height apart touch

struct Pieces {
  std::size_t count = 0;      // pieces holding at least one segment of positive length
  double largest_length = 0;  // total segment length of the longest piece
  double total_length = 0;    // of all segments
  // Piece of each node, 0-based in order of first appearance; pieces without length and
  // nodes on no segment get kNoPiece.
  std::vector<std::size_t> piece_of_node;
};

inline constexpr std::size_t kNoPiece = std::size_t(-1);

Pieces find_pieces(const Skeleton& skeleton);

}  // namespace ramus::shape
