// The C boundary of the runtime (ramus_runtime.h): every entry point runs its body through
// guarded(), so no exception crosses into C, and a failure leaves a message in the caller's
// buffer. Shared by the .cpp files that implement the API.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstring>
#include <exception>
#include <new>

namespace ramus::runtime {

inline void set_error(char* err, std::size_t errlen, const char* message) {
  if (!err || errlen == 0) return;
  const std::size_t n = std::min(std::strlen(message), errlen - 1);
  std::memcpy(err, message, n);
  err[n] = '\0';
}

// Runs f(), turning any exception into `fallback` and a message.
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
