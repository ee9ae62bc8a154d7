#pragma once

#include <stdexcept>

namespace ramus::skeleton_infer {

// Thrown when there is nothing to infer from (no segment at all).
struct InferError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace ramus::skeleton_infer
