#include "cli/read_file.h"

#include <fstream>
#include <sstream>

#include "cli/command.h"

namespace ramus::cli {

std::string read_file_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw UserError("cannot open " + path);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

}  // namespace ramus::cli
