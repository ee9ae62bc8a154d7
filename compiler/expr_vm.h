// The expression VM: a stack machine over doubles that runs the bytecode of ir::Code.
//
// Every operation that could produce a NaN or an infinity checks its result, so a bad parameter
// is reported (ExprError, naming the cause) instead of flowing silently into the string. Callers
// add the production and the step to the message (compiler/derive.cpp).
#pragma once

#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "compiler/ir.h"
#include "core/rng.h"

namespace ramus {

struct ExprError : std::runtime_error {
  ExprError(std::string msg, ir::CodeId c) : std::runtime_error(std::move(msg)), code(c) {}
  ir::CodeId code;
};

// A module's random stream, created on first use: most modules never draw, and keying a stream
// costs a few hashes (docs/language.md, Randomness).
class LazyRng {
 public:
  LazyRng(std::uint64_t seed, std::uint64_t a, std::uint64_t b) : seed_(seed), a_(a), b_(b) {}
  Rng& get() {
    if (!ready_) {
      rng_ = Rng::stream(seed_, a_, b_);
      ready_ = true;
    }
    return rng_;
  }

 private:
  std::uint64_t seed_, a_, b_;
  bool ready_ = false;
  Rng rng_;
};

// Runs code `c` with formal parameters `slots`; throws ExprError on a non-finite result.
double run_code(const ir::Grammar& g, ir::CodeId c, const double* slots, LazyRng& rng);

// The hot path: constants, bare parameters and `param op constant` skip the VM (which also
// gives the error message when such a result is not finite).
inline double eval(const ir::Grammar& g, ir::CodeId c, const double* slots, LazyRng& rng) {
  const ir::Code& code = g.codes[c];
  switch (code.shape) {
    case ir::Code::Shape::Constant:
      return code.value;
    case ir::Code::Shape::Param:
      return slots[code.slot];
    case ir::Code::Shape::ParamOpConst: {
      const double x = slots[code.slot];
      double r = code.op == ir::Op::Add   ? x + code.value
                 : code.op == ir::Op::Sub ? x - code.value
                 : code.op == ir::Op::Mul ? x * code.value
                                          : x / code.value;
      if (std::isfinite(r)) return r;
      break;
    }
    case ir::Code::Shape::General:
      break;
  }
  return run_code(g, c, slots, rng);
}

}  // namespace ramus
