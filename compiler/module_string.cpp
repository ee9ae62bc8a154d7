#include "compiler/module_string.h"

#include <cctype>
#include <charconv>
#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <mutex>
#include <new>

#if defined(__linux__)
#include <sys/mman.h>
#include <unistd.h>
#endif

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

// Large buffers (2 MB and more) freed by one derivation are kept for the next one, at most
// kKeptLarge of them and an eighth of physical memory: a process that derives again (a
// benchmark's repeats, an editor's live preview, a search over grammars) then writes to pages it
// already has instead of the kernel supplying fresh zeroed ones, about a microsecond per 4 KB
// page (docs/engine.md, "The string"). A kept buffer stays resident while it is in use again and
// again: giving its pages back lazily (MADV_FREE) as soon as it is kept made every page dearer
// to write again (the kernel cleans it and drops it from the TLB; on the development machine a
// derivation of (b) in bench_lsystem took 2.6 instead of 1.8 ns a module). Only a buffer that no
// request has taken for kIdleSeconds is given back lazily, checked whenever a large buffer is
// kept or taken: the kernel may then take its pages when it runs short of memory, and reading
// one gives zeros, which does not matter because every element is written before it is read.
namespace {

constexpr int kKeptLarge = 32;
constexpr double kIdleSeconds = 1.0;
struct KeptLarge {
  void* p = nullptr;
  std::size_t bytes = 0;
  std::chrono::steady_clock::time_point since{};  // when it was kept
  bool lazy = false;                              // its pages were given back lazily
};
KeptLarge kept_large[kKeptLarge];
std::size_t kept_large_bytes = 0;

std::size_t large_keep_limit() {
#if defined(__linux__)
  const long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGESIZE);
  if (pages > 0 && page > 0) return std::size_t(pages) * std::size_t(page) / 8;
#endif
  return 0;
}

// Gives the whole pages inside [p, p + bytes) back lazily.
void free_lazily(void* p, std::size_t bytes) {
#if defined(__linux__)
  const auto page = std::uintptr_t(sysconf(_SC_PAGESIZE));
  const auto b = (std::uintptr_t(p) + page - 1) & ~(page - 1);
  const auto e = (std::uintptr_t(p) + bytes) & ~(page - 1);
  if (e > b) madvise(reinterpret_cast<void*>(b), e - b, MADV_FREE);
#else
  (void)p;
  (void)bytes;
#endif
}

// Gives back lazily every kept large buffer idle since before `now - kIdleSeconds` (called with
// kept_mutex held).
void free_idle_lazily(std::chrono::steady_clock::time_point now) {
  for (KeptLarge& k : kept_large) {
    if (k.p && !k.lazy && now - k.since >= std::chrono::duration<double>(kIdleSeconds)) {
      free_lazily(k.p, k.bytes);
      k.lazy = true;
    }
  }
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
  {
    // The smallest kept buffer that holds `bytes` and is at most twice as large.
    std::lock_guard<std::mutex> lock(kept_mutex);
    free_idle_lazily(std::chrono::steady_clock::now());
    KeptLarge* best = nullptr;
    for (KeptLarge& k : kept_large) {
      if (k.p && k.bytes >= bytes && k.bytes / 2 <= bytes && (!best || k.bytes < best->bytes)) {
        best = &k;
      }
    }
    if (best) {
      void* p = best->p;
      kept_large_bytes -= best->bytes;
      *best = {};
      return p;
    }
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
  } else {
    static const std::size_t limit = large_keep_limit();
    const auto now = std::chrono::steady_clock::now();
    std::lock_guard<std::mutex> lock(kept_mutex);
    free_idle_lazily(now);
    if (kept_large_bytes + bytes <= limit) {
      for (KeptLarge& k : kept_large) {
        if (!k.p) {
          k = {p, bytes, now, false};  // at least `bytes`: it may have been allocated larger
          kept_large_bytes += bytes;
          return;
        }
      }
    }
  }
  std::free(p);
}

std::size_t release_kept_buffers() noexcept {
  std::lock_guard<std::mutex> lock(kept_mutex);
  std::size_t released = 0;
  for (Kept& k : kept) {
    if (k.p) {
      std::free(k.p);
      released += k.bytes;
    }
    k = {};
  }
  for (KeptLarge& k : kept_large) {
    if (k.p) {
      std::free(k.p);
      released += k.bytes;
    }
    k = {};
  }
  kept_large_bytes = 0;
  return released;
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
