#include "compiler/driver/scan_args.h"

#include <sstream>

#include "compiler/driver/command.h"

namespace ramus::cli {

Vec3 parse_scanner(const std::string& text) {
  std::istringstream in(text);
  Vec3 v;
  char c1 = 0, c2 = 0;
  if (!(in >> v.x >> c1 >> v.y >> c2 >> v.z) || c1 != ',' || c2 != ',' || !(in >> std::ws).eof() ||
      !is_finite(v)) {
    throw UserError("--scanner expects three numbers x,y,z, not '" + text + "'");
  }
  return v;
}

std::string file_name(const std::string& path) {
  std::size_t slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

}  // namespace ramus::cli
