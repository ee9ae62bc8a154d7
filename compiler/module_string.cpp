#include "compiler/module_string.h"

#include <cctype>
#include <charconv>
#include <cstdlib>
#include <mutex>
#include <new>

#include "core/number_text.h"

namespace ramus {

namespace {

// The kept mid-size buffers: at most kKept, each a power of two in [kMidBuffer, kLargeBuffer),
// so at most 16 MB stay with the process. A global, so they stay reachable (no leak reported).
constexpr int kKept = 8;
struct Kept {
  void* p = nullptr;
  std::size_t bytes = 0;
};
std::mutex kept_mutex;
Kept kept[kKept];

std::size_t size_class(std::size_t bytes) {
  std::size_t c = kMidBuffer;
  while (c < bytes) c *= 2;
  return c;
}

}  // namespace

void* allocate_buffer(std::size_t bytes) {
  if (bytes < kLargeBuffer) {
    const std::size_t c = size_class(bytes);
    {
      std::lock_guard<std::mutex> lock(kept_mutex);
      for (Kept& k : kept) {
        if (k.p && k.bytes == c) {
          void* p = k.p;
          k.p = nullptr;
          return p;
        }
      }
    }
    void* p = std::malloc(c);
    if (!p) throw std::bad_alloc();
    return p;
  }
  void* p = std::malloc(bytes);
  if (!p) throw std::bad_alloc();
  return p;
}

void free_buffer(void* p, std::size_t bytes) noexcept {
  if (bytes < kLargeBuffer) {
    const std::size_t c = size_class(bytes);
    std::lock_guard<std::mutex> lock(kept_mutex);
    for (Kept& k : kept) {
      if (!k.p) {
        k = {p, c};
        return;
      }
    }
  }
  std::free(p);
}

namespace {
bool is_word(const std::string& name) {
  return !name.empty() && (std::isalpha(static_cast<unsigned char>(name[0])) || name[0] == '_');
}
}  // namespace

std::string to_text(const ir::Grammar& g, const ModuleString& s) {
  std::string out;
  out.reserve(s.size() * 2);
  const std::string* prev = nullptr;  // name of the previous module when it had no parameters
  for (std::size_t i = 0; i < s.size(); ++i) {
    const std::string& name = g.symbols[s.symbol(i)].name;
    // A declared multi-letter name next to another name would read as different modules
    // (`Apex B` is not `ApexB`): separate such neighbours with a blank.
    if (prev && (prev->size() > 1 || name.size() > 1) && is_word(*prev) && is_word(name)) {
      out += ' ';
    }
    out += name;
    const std::uint32_t n = s.nparams(i);
    prev = n == 0 ? &name : nullptr;
    if (n == 0) continue;
    out += '(';
    for (std::uint32_t k = 0; k < n; ++k) {
      if (k) out += ',';
      append_shortest(out, s.param(i, k));
    }
    out += ')';
  }
  return out;
}

}  // namespace ramus
