#include "cli/defines.h"

#include <cctype>
#include <charconv>
#include <cmath>

#include "cli/command.h"
#include "grammar/modules.h"

namespace ramus::cli {

namespace {}  // namespace

std::pair<std::string, double> parse_define(const std::string& text) {
  const auto eq = text.find('=');
  if (eq == std::string::npos) {
    throw UserError("-D " + text + ": expected name=value");
  }
  std::string name = text.substr(0, eq);
  std::string value = text.substr(eq + 1);
  if (!is_identifier(name)) throw UserError("-D " + text + ": '" + name + "' is not a name");
  const char* b = value.data();
  const char* e = b + value.size();
  if (b != e && *b == '+') ++b;  // from_chars does not accept a leading '+'
  double v = 0;
  auto r = std::from_chars(b, e, v);
  if (value.empty() || r.ec != std::errc() || r.ptr != e || !std::isfinite(v)) {
    throw UserError("-D " + text + ": '" + value + "' is not a finite number");
  }
  return {name, v};
}

std::vector<std::pair<std::string, double>> parse_defines(const std::vector<std::string>& texts) {
  std::vector<std::pair<std::string, double>> out;
  for (const std::string& t : texts) {
    auto d = parse_define(t);
    bool replaced = false;
    for (auto& o : out) {
      if (o.first == d.first) {
        o.second = d.second;
        replaced = true;
      }
    }
    if (!replaced) out.push_back(d);
  }
  return out;
}

}  // namespace ramus::cli
