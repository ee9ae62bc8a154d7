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

// Rng::stream(seed, a, b) (core/rng.h) in two halves, for the many streams of a derivation pass
// that share seed and a: the prefix is hashed once per pass, each module's stream then costs two
// mixes instead of four. tests/compiler/test_stochastic.cpp checks it equals Rng::stream.
constexpr std::uint64_t stream_prefix(std::uint64_t seed, std::uint64_t a) {
  return mix64(seed ^ 0x5851f42d4c957f2dULL) ^ mix64(a + 0x9e3779b97f4a7c15ULL);
}
constexpr Rng stream_from_prefix(std::uint64_t prefix, std::uint64_t b) {
  return Rng(mix64(prefix ^ mix64(b + 0x632be59bd9b4e019ULL) * 3));
}

// A module's random stream, created on first use: most modules never draw, and keying a stream
// costs a few hashes (docs/language.md, Randomness).
class LazyRng {
 public:
  LazyRng(std::uint64_t seed, std::uint64_t a, std::uint64_t b)
      : prefix_(stream_prefix(seed, a)), b_(b) {}
  // prefix: stream_prefix(seed, a), hashed once per pass.
  LazyRng(std::uint64_t prefix, std::uint64_t b) : prefix_(prefix), b_(b) {}
  Rng& get() {
    if (!ready_) {
      rng_ = stream_from_prefix(prefix_, b_);
      ready_ = true;
    }
    return rng_;
  }

 private:
  std::uint64_t prefix_, b_;
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
