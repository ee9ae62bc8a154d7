// The C API's opaque handles and its error guard, shared by the files that implement
// ramus_runtime.h (ramus_runtime.cpp: load and grow; ramus_mesher.cpp: the mesher). Internal:
// nothing outside runtime/ includes it.
#pragma once

#include <algorithm>
#include <cstring>
#include <exception>
#include <new>

#include "compiler/ir.h"
#include "core/skeleton.h"

struct ramus_grammar {
  ramus::ir::Grammar g;
};

struct ramus_skeleton {
  ramus::Skeleton s;
};

namespace ramus::runtime {

inline void set_error(char* err, std::size_t errlen, const char* message) {
  if (!err || errlen == 0) return;
  const std::size_t n = std::min(std::strlen(message), errlen - 1);
  std::memcpy(err, message, n);
  err[n] = '\0';
}

// Runs f(), turning any exception into `fallback` and a message: exceptions never cross the C
// boundary.
template <typename T, typename F>
T guarded(char* err, std::size_t errlen, T fallback, F&& f) {
  set_error(err, errlen, "");
  try {
    return f();
  } catch (const std::bad_alloc&) {
    set_error(err, errlen, "out of memory");
  } catch (const std::exception& e) {
    set_error(err, errlen, e.what());
  } catch (...) {
    set_error(err, errlen, "unknown error");
  }
  return fallback;
}

}  // namespace ramus::runtime
