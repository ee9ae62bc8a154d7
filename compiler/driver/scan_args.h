// Small helpers shared by the subcommands that read scans (compress, enhance).
#pragma once

#include <string>

#include "core/vec3.h"

namespace ramus::cli {

// "x,y,z" -> Vec3; throws UserError naming the text otherwise.
Vec3 parse_scanner(const std::string& text);

// The last path component, for table rows.
std::string file_name(const std::string& path);

}  // namespace ramus::cli
