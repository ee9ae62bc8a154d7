#include "formats/detail/mapped_file.h"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>

#include "formats/detail/reader_util.h"

namespace ramus::formats_detail {

MappedFile::MappedFile(const std::string& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) fail(path, std::string("cannot open the file (") + std::strerror(errno) + ")");
  struct stat st {};
  if (::fstat(fd, &st) == 0 && S_ISREG(st.st_mode) && st.st_size > 0) {
    void* p = ::mmap(nullptr, std::size_t(st.st_size), PROT_READ, MAP_PRIVATE, fd, 0);
    if (p != MAP_FAILED) {
      map_ = p;
      size_ = std::size_t(st.st_size);
      ::madvise(map_, size_, MADV_SEQUENTIAL);
      view_ = std::string_view(static_cast<const char*>(map_), size_);
    }
  }
  ::close(fd);
  if (map_ || (S_ISREG(st.st_mode) && st.st_size == 0)) return;
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(path, std::string("cannot open the file (") + std::strerror(errno) + ")");
  copy_.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  if (in.bad()) fail(path, "cannot read the file");
  view_ = copy_;
}

MappedFile::~MappedFile() {
  if (map_) ::munmap(map_, size_);
}

void MappedFile::release_before(std::size_t byte) {
  if (!map_) return;
  const std::size_t page = std::size_t(::sysconf(_SC_PAGESIZE));
  byte = std::min(byte, size_) / page * page;
  if (byte < released_ + kReleaseStep) return;
  // MADV_DONTNEED on a private read-only file mapping drops the pages from this process; a
  // later access faults them in again from the page cache, unchanged.
  ::madvise(static_cast<char*>(map_) + released_, byte - released_, MADV_DONTNEED);
  released_ = byte;
}

}  // namespace ramus::formats_detail
