#include "formats/rmb/rmb_decompiled_number.h"

#include <cmath>
#include <utility>

#include "core/number_text.h"

namespace ramus {

ast::Expr decompiled_number(double v) {
  if (!std::isfinite(v)) {
    throw DecompileError("the number " + shortest_text(v) + " has no .ramus spelling");
  }
  ast::Expr e;
  if (std::signbit(v)) {
    e.node = ast::Unary{ast::UnaryOp::Neg, ast::Box<ast::Expr>(decompiled_number(-v))};
  } else {
    e.node = ast::NumberLit{v, shortest_text(v)};
  }
  return e;
}

}  // namespace ramus
