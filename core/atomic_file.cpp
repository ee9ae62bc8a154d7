#include "core/atomic_file.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <unistd.h>

#include "core/rng.h"

namespace ramus {

namespace fs = std::filesystem;

void write_file_atomically(const std::string& path,
                           const std::function<void(std::ostream&)>& write) {
  fs::path target(path);
  fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) {
    throw WriteError("cannot write '" + path + "': directory '" + dir.string() +
                     "' does not exist");
  }
  // The temporary's name only needs to be unique, not reproducible.
  Rng rng(std::uint64_t(::getpid()) * 0x9e3779b97f4a7c15ULL ^ std::uint64_t(std::random_device{}()));
  char suffix[32];
  std::snprintf(suffix, sizeof suffix, ".tmp%08llx", (unsigned long long)(rng.next_u64() & 0xffffffffULL));
  fs::path tmp = dir / (target.filename().string() + suffix);
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) {
      throw WriteError("cannot write '" + path + "': " + std::strerror(errno));
    }
    try {
      write(out);
      out.flush();
    } catch (...) {
      out.close();
      fs::remove(tmp, ec);
      throw;
    }
    if (!out) {
      out.close();
      fs::remove(tmp, ec);
      throw WriteError("cannot write '" + path + "': write failed (disk full?)");
    }
  }
  fs::rename(tmp, target, ec);
  if (ec) {
    fs::remove(tmp, ec);
    throw WriteError("cannot write '" + path + "': " + ec.message());
  }
}

void write_file_atomically(const std::string& path, std::string_view bytes) {
  write_file_atomically(path, [&](std::ostream& out) { out.write(bytes.data(), std::streamsize(bytes.size())); });
}

}  // namespace ramus
