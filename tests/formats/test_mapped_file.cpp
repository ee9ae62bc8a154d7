// MappedFile: the readers' view of a file, whose passed pages leave the resident set.
#include <unistd.h>

#include <catch2/catch.hpp>
#include <fstream>
#include <string>

#include "format_test_util.h"
#include "formats/detail/mapped_file.h"

using namespace ramus;
using ramus::formats_detail::MappedFile;

namespace {

// This process's resident set in bytes (Linux /proc/self/statm, second field in pages).
std::size_t resident_bytes() {
  std::ifstream in("/proc/self/statm");
  std::size_t size = 0, resident = 0;
  in >> size >> resident;
  return resident * std::size_t(::sysconf(_SC_PAGESIZE));
}

}  // namespace

TEST_CASE("a mapped file's released pages leave the resident set and read back unchanged",
          "[mapped]") {
  const auto dir = test::temp_dir("mapped");
  const std::string path = (dir / "big.bin").string();
  constexpr std::size_t kSize = std::size_t(64) << 20;
  {
    std::string block(1 << 20, '\0');
    for (std::size_t i = 0; i < block.size(); ++i) block[i] = char(i * 7 + 3);
    std::ofstream out(path, std::ios::binary);
    for (std::size_t i = 0; i < kSize / block.size(); ++i)
      out.write(block.data(), std::streamsize(block.size()));
  }
  MappedFile file(path);
  REQUIRE(file.bytes().size() == kSize);
  auto checksum = [&] {
    std::uint64_t sum = 0;
    for (std::size_t i = 0; i < kSize; i += 512) sum += std::uint8_t(file.bytes()[i]);
    return sum;
  };
  const std::uint64_t first = checksum();  // touches every page
  const std::size_t touched = resident_bytes();
  file.release_before(kSize);
  const std::size_t released = resident_bytes();
  CHECK(touched - released >= kSize / 2);
  CHECK(checksum() == first);  // the pages fault back in from the page cache
  // Releases closer than kReleaseStep to the last one do nothing; restart() counts afresh.
  file.restart();
  file.release_before(MappedFile::kReleaseStep - 4096);
  CHECK(resident_bytes() + kSize / 2 > touched);
  std::filesystem::remove_all(dir);
}

TEST_CASE("a file that cannot be mapped is read into memory, a missing one is an error",
          "[mapped]") {
  CHECK(test::error_of([] {
          MappedFile f("/nonexistent/ramus.las");
        }).find("cannot open the file") != std::string::npos);
  const auto dir = test::temp_dir("mapped_empty");
  { std::ofstream(dir / "empty.xyz"); }
  MappedFile empty((dir / "empty.xyz").string());
  CHECK(empty.bytes().empty());
  std::filesystem::remove_all(dir);
}
