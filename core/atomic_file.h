// Writing outputs safely: everything goes to a temporary file beside the target and is renamed
// into place only when complete, so a failed or interrupted write never leaves a partial file.
// On Linux the temporary is unnamed (O_TMPFILE) while it is written, so even a process killed
// by SIGKILL leaves nothing behind in the folder (atomic_file.cpp).
#pragma once

#include <functional>
#include <ostream>
#include <stdexcept>
#include <string>
#include <string_view>

namespace ramus {

struct WriteError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Calls `write` with a binary stream to a temporary file in the directory of `path`; when it
// returns normally and the stream is good, renames the temporary over `path`. Otherwise removes
// the temporary and throws WriteError with a message that names `path` and the cause.
void write_file_atomically(const std::string& path,
                           const std::function<void(std::ostream&)>& write);

// Convenience for contents already in memory.
void write_file_atomically(const std::string& path, std::string_view bytes);

}  // namespace ramus
