#include "cli/read_file.h"


#include "cli/command.h"
#include "core/input_file.h"

namespace ramus::cli {

std::string read_file_bytes(const std::string& path) {
  std::string bytes, error;
  if (!read_input_file(path, bytes, error)) throw UserError(path + ": " + error);
  return bytes;
}

}  // namespace ramus::cli
