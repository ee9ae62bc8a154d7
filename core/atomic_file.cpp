#include "core/atomic_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <random>
#include <streambuf>

#include "core/rng.h"

namespace ramus {

namespace fs = std::filesystem;

namespace {

// A buffered std::streambuf over a file descriptor: the writers take an std::ostream, and an
// O_TMPFILE file exists only as a descriptor. `failed` records the errno of the first failure.
class FdBuf : public std::streambuf {
 public:
  explicit FdBuf(int fd) : fd_(fd) { setp(buf_, buf_ + sizeof buf_); }
  int failed = 0;

 protected:
  int_type overflow(int_type ch) override {
    if (!drain()) return traits_type::eof();
    if (!traits_type::eq_int_type(ch, traits_type::eof())) {
      *pptr() = traits_type::to_char_type(ch);
      pbump(1);
    }
    return traits_type::not_eof(ch);
  }
  int sync() override { return drain() ? 0 : -1; }

 private:
  bool drain() {
    const char* p = pbase();
    while (p < pptr() && failed == 0) {
      const ssize_t n = ::write(fd_, p, std::size_t(pptr() - p));
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) failed = n < 0 ? errno : EIO;
      if (n > 0) p += n;
    }
    setp(buf_, buf_ + sizeof buf_);
    return failed == 0;
  }
  int fd_;
  char buf_[1 << 16];
};

// A name beside the target that no one else uses: `<file>.tmpXXXXXXXX`.
fs::path temporary_name(const fs::path& dir, const fs::path& target) {
  // The temporary's name only needs to be unique, not reproducible.
  Rng rng(std::uint64_t(::getpid()) * 0x9e3779b97f4a7c15ULL ^
          std::uint64_t(std::random_device{}()));
  char suffix[32];
  std::snprintf(suffix, sizeof suffix, ".tmp%08llx",
                (unsigned long long)(rng.next_u64() & 0xffffffffULL));
  return dir / (target.filename().string() + suffix);
}

}  // namespace

// The file is written as an unnamed O_TMPFILE inode of the target's directory (Linux >= 3.11 on
// ext4, xfs, btrfs, tmpfs): a process killed while writing, even by SIGKILL, leaves nothing in the
// folder, because the kernel frees an unnamed inode with its last descriptor. Once complete it
// gets a temporary name (linkat through /proc/self/fd) and is renamed over the target, the one
// step that replaces the old file; only a kill between those two calls (microseconds) can leave
// a `.tmp` file behind. Where O_TMPFILE is not supported the file is a named temporary from the
// start (the old behaviour) and a kill while writing leaves it behind.
void write_file_atomically(const std::string& path,
                           const std::function<void(std::ostream&)>& write) {
  fs::path target(path);
  fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) {
    throw WriteError("cannot write '" + path + "': directory '" + dir.string() +
                     "' does not exist");
  }
  const fs::path tmp = temporary_name(dir, target);
  bool named = false;
#ifdef O_TMPFILE
  int fd = ::open(dir.c_str(), O_TMPFILE | O_WRONLY | O_CLOEXEC, 0666);
#else
  int fd = -1;
  errno = EOPNOTSUPP;
#endif
  if (fd < 0 && errno != EACCES && errno != EROFS && errno != ENOSPC && errno != EDQUOT) {
    fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    named = true;
  }
  if (fd < 0) throw WriteError("cannot write '" + path + "': " + std::strerror(errno));
  auto discard = [&] {
    ::close(fd);
    if (named) fs::remove(tmp, ec);
  };
  FdBuf buf(fd);
  std::ostream out(&buf);
  try {
    write(out);
    out.flush();
  } catch (...) {
    discard();
    throw;
  }
  if (!out || buf.failed != 0) {
    const int err = buf.failed;
    discard();
    throw WriteError("cannot write '" + path +
                     "': " + (err ? std::string(std::strerror(err)) : "write failed (disk full?)"));
  }
  if (!named) {
    const std::string self = "/proc/self/fd/" + std::to_string(fd);
    if (::linkat(AT_FDCWD, self.c_str(), AT_FDCWD, tmp.c_str(), AT_SYMLINK_FOLLOW) != 0) {
      const int err = errno;
      ::close(fd);
      throw WriteError("cannot write '" + path + "': " + std::strerror(err));
    }
  }
  if (::close(fd) != 0) {
    const int err = errno;
    fs::remove(tmp, ec);
    throw WriteError("cannot write '" + path + "': " + std::strerror(err));
  }
  fs::rename(tmp, target, ec);
  if (ec) {
    fs::remove(tmp, ec);
    throw WriteError("cannot write '" + path + "': " + ec.message());
  }
}

void write_file_atomically(const std::string& path, std::string_view bytes) {
  write_file_atomically(
      path, [&](std::ostream& out) { out.write(bytes.data(), std::streamsize(bytes.size())); });
}

}  // namespace ramus
