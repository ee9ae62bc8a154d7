// ramus infer --method wavelet (being written).
#include "compiler/driver/infer_methods.h"

namespace ramus::cli {

InferRunner add_infer_wavelet_options(CLI::App&, const GlobalOptions&) {
  return [](const InferCommonArgs&) -> int { throw UserError("--method wavelet is not available yet"); };
}

}  // namespace ramus::cli
