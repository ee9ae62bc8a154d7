// Whole-file input for the commands that read binary files (.rmb).
#pragma once

#include <string>

namespace ramus::cli {

// The bytes of the file at `path`; throws UserError when it cannot be opened.
std::string read_file_bytes(const std::string& path);

}  // namespace ramus::cli
