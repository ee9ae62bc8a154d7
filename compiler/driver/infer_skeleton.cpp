// ramus infer --method skeleton (being written).
#include "compiler/driver/infer_methods.h"

namespace ramus::cli {

InferRunner add_infer_skeleton_options(CLI::App&, const GlobalOptions&) {
  return [](const InferCommonArgs&) -> int { throw UserError("--method skeleton is not available yet"); };
}

}  // namespace ramus::cli
