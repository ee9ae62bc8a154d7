// The error of infer/shape/: inputs the shape measures cannot be taken on (a scan without
// height, a skeleton so long that sampling it would not fit in memory). The CLI shows the
// message and exits with 1.
#pragma once

#include <stdexcept>

namespace ramus::shape {

struct ShapeError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace ramus::shape
