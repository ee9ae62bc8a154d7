// A file mapped read-only into memory, so a reader walks its bytes without a copy, and hands
// back the pages it has passed (release_before), so a sequential read of a file larger than
// memory keeps only a window of it resident. Falls back to reading the file into memory when it
// cannot be mapped (pipes, special files).
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace ramus::formats_detail {

class MappedFile {
 public:
  // Throws FormatError (through fail) when the file cannot be opened or read.
  explicit MappedFile(const std::string& path);
  ~MappedFile();
  MappedFile(const MappedFile&) = delete;
  MappedFile& operator=(const MappedFile&) = delete;

  std::string_view bytes() const { return view_; }
  // The reader is done with the bytes before `byte`: their whole pages leave the process's
  // resident set (they stay in the page cache; touching them again reads them back). Calls
  // that do not pass the last release by at least kReleaseStep do nothing, so readers may call
  // it often.
  void release_before(std::size_t byte);
  // A new pass over the file starts: releases count from its start again.
  void restart() { released_ = 0; }

  static constexpr std::size_t kReleaseStep = std::size_t(16) << 20;

 private:
  void* map_ = nullptr;
  std::size_t size_ = 0;
  std::string copy_;  // when not mapped
  std::string_view view_;
  std::size_t released_ = 0;
};

}  // namespace ramus::formats_detail
