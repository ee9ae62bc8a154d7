#include "core/input_file.h"

#include <atomic>
#include <cerrno>
#include <cstring>
#include <fstream>

namespace ramus {
namespace {

std::atomic<std::uint64_t> g_max_input_file_bytes{kDefaultMaxInputFileBytes};
std::atomic<std::uint64_t> g_max_input_points{kDefaultMaxInputPoints};

}  // namespace

std::uint64_t max_input_file_bytes() { return g_max_input_file_bytes.load(); }

void set_max_input_file_bytes(std::uint64_t bytes) { g_max_input_file_bytes.store(bytes); }

std::uint64_t max_input_points() { return g_max_input_points.load(); }

void set_max_input_points(std::uint64_t points) { g_max_input_points.store(points); }

std::string input_file_size_error(std::uint64_t bytes) {
  const std::uint64_t limit = max_input_file_bytes();
  if (bytes <= limit) return "";
  return "the file has " + std::to_string(bytes) + " bytes, more than the limit of " +
         std::to_string(limit) + " (--max-file-size)";
}

std::string input_file_size_error(const std::filesystem::path& path) {
  std::error_code ec;
  const std::uintmax_t size = std::filesystem::file_size(path, ec);
  return ec ? std::string() : input_file_size_error(std::uint64_t(size));
}

bool read_input_file(const std::filesystem::path& path, std::string& bytes, std::string& error) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {
    error = "is a directory";
    return false;
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    error = std::string("cannot open the file (") + std::strerror(errno) + ")";
    return false;
  }
  in.seekg(0, std::ios::end);
  const std::streamoff size = in.tellg();
  if (size < 0) {
    error = "cannot determine the file's size";
    return false;
  }
  error = input_file_size_error(std::uint64_t(size));
  if (!error.empty()) return false;
  in.seekg(0, std::ios::beg);
  bytes.assign(std::size_t(size), '\0');
  if (size > 0 && !in.read(bytes.data(), size)) {
    error = "cannot read the file";
    return false;
  }
  return true;
}

}  // namespace ramus
